use dynamics_runtime::Dynamics;

// A URDF joint whose <mimic> names itself.
#[derive(Dynamics)]
#[dynamics(urdf = "mimic_itself.urdf")]
struct Arm;

fn main() {}
