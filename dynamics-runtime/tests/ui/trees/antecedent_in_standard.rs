use dynamics_runtime::Dynamics;

// An antecedent column in a standard D-H table: trees are modified-convention only.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 0, 0], [q, 0, 0.5, 0], [q, 0, 0.5, 0, 1, 90 deg, 0.1]], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
