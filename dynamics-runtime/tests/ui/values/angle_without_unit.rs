use dynamics_runtime::Dynamics;

// A twist of 90 with no unit would be 90 radians: almost surely a forgotten `deg`.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 90]], link(mass = 1))]
struct Arm;

fn main() {}
