use dynamics_runtime::Dynamics;

// A misspelt joint type.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolut(axis = [0, 0, 1])], link(mass = 1))]
struct Arm;

fn main() {}
