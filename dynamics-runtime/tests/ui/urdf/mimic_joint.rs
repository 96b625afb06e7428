use dynamics_runtime::Dynamics;

// A <mimic> naming a joint the file does not have. The path is relative to this file:
// trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(urdf = "mimic_joint.urdf")]
struct Arm;

fn main() {}
