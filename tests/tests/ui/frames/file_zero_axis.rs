use dynamics_runtime::Dynamics;

// The path is relative to the crate's Cargo.toml, which for trybuild is target/tests/trybuild/<crate>.
#[derive(Dynamics)]
#[dynamics(file = "../../../../tests/tests/ui/frames/file_zero_axis.toml")]
struct Arm;

fn main() {}
