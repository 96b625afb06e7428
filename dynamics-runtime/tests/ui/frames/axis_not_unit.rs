use dynamics_runtime::Dynamics;

// An axis of length 2 is not a unit vector.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [prismatic(axis = [0, 2, 0])], link(mass = 1))]
struct Arm;

fn main() {}
