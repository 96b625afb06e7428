use dynamics_runtime::Dynamics;

// The path is relative to the crate's Cargo.toml, which for trybuild is target/tests/trybuild/<crate>.
#[derive(Dynamics)]
#[dynamics(urdf = "../../../../tests/tests/ui/urdf/non_unit_axis.urdf")]
struct Arm;

fn main() {}
