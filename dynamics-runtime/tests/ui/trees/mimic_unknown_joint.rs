use dynamics_runtime::Dynamics;

// A mimic joint following a joint past the last.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(), revolute(mimic = (joint = 4))], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
