use dynamics_runtime::Dynamics;

// A mimic joint following a mimic joint.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(mimic = (joint = 1)), revolute(mimic = (joint = 2, multiplier = -1))], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
