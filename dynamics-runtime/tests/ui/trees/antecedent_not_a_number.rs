use dynamics_runtime::Dynamics;

// An antecedent that is not a row's number.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], convention = modified, dh = [[q, 0, 0, 0], [q, 0, 0.5, 0, 0.5, 0, 0], [q, 0, 0.5, 0]], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
