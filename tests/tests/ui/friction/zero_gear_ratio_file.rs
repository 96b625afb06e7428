use dynamics_runtime::Dynamics;

// The path is relative to the crate's Cargo.toml, which for trybuild is target/tests/trybuild/<crate>.
#[derive(Dynamics)]
#[dynamics(file = "../../../../tests/tests/ui/friction/zero_gear_ratio_file.toml")]
struct Arm;

fn main() {}
