use dynamics_runtime::Dynamics;

// A tip fixed to the base (its pose and Jacobian constants), on its own string.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tips = ["fore", "stand"])]
struct Arm;

fn main() {}
