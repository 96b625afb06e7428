use dynamics_runtime::Dynamics;

// A URDF link with two parents.
#[derive(Dynamics)]
#[dynamics(urdf = "two_parents.urdf")]
struct Arm;

fn main() {}
