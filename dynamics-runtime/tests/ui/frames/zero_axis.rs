use dynamics_runtime::Dynamics;

// A joint turns about no axis.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(axis = [0, 0, 0])], link(mass = 1))]
struct Arm;

fn main() {}
