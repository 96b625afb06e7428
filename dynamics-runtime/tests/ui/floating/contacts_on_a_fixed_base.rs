use dynamics_runtime::Dynamics;

// `contacts = true` asks for a floating base's contact terms: a fixed base has none.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1), contacts = true)]
struct Arm;

fn main() {}
