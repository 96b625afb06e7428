use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(urdf = "non_unit_axis.urdf")]
struct Arm;

fn main() {}
