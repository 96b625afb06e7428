use dynamics_runtime::Dynamics;

// The path is relative to the crate's Cargo.toml, which for trybuild is target/tests/trybuild/<crate>.
#[derive(Dynamics)]
#[dynamics(file = "../../../../tests/tests/ui/frames/file_mixes_dh_and_origin.toml")]
struct Arm;

fn main() {}
