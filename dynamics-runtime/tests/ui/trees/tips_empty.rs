use dynamics_runtime::Dynamics;

// An empty tips list.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tips = [])]
struct Arm;

fn main() {}
