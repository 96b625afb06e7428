use dynamics_runtime::Dynamics;

// tips naming a link that is not below the base.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", base = "upper", tips = ["fore", "ground"])]
struct Arm;

fn main() {}
