use dynamics_runtime::Dynamics;

// An antecedent row after its child.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], convention = modified, dh = [[q, 0, 0, 0], [q, 0, 0.5, 0, 3, 0, 0], [q, 0, 0.5, 0]], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
