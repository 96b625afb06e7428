use dynamics_runtime::Dynamics;

// tips naming a link the URDF does not have.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tips = ["fore", "hand"])]
struct Arm;

fn main() {}
