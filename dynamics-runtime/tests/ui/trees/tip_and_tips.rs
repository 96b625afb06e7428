use dynamics_runtime::Dynamics;

// tip and tips together.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tip = "fore", tips = ["side"])]
struct Arm;

fn main() {}
