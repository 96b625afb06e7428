use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(file = "empty_joints.json")]
struct Arm;

fn main() {}
