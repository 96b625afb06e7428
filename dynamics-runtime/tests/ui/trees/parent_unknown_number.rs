use dynamics_runtime::Dynamics;

// A parent number past the last joint.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(parent = 5), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
