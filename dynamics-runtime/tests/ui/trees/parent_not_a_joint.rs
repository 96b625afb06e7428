use dynamics_runtime::Dynamics;

// A parent that is neither a number nor a name.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(parent = true), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
