use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(file = "file_dh_joint_among_frames.toml")]
struct Arm;

fn main() {}
