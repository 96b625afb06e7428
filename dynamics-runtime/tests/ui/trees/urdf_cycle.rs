use dynamics_runtime::Dynamics;

// A URDF whose joints make a loop.
#[derive(Dynamics)]
#[dynamics(urdf = "cycle.urdf", base = "ground")]
struct Arm;

fn main() {}
