use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(file = "zero_gear_ratio_file.toml")]
struct Arm;

fn main() {}
