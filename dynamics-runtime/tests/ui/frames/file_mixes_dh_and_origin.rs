use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(file = "file_mixes_dh_and_origin.toml")]
struct Arm;

fn main() {}
