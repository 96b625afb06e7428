use dynamics_runtime::Dynamics;

// A URDF with two root links and no base named.
#[derive(Dynamics)]
#[dynamics(urdf = "two_roots.urdf")]
struct Arm;

fn main() {}
