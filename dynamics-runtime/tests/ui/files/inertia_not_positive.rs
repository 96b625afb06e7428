use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(file = "inertia_not_positive.json")]
struct Arm;

fn main() {}
