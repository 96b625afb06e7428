use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(
    urdf = "arm.urdf",
    tool = [0, 0, 0.1, 0, 0, 0],
)]
struct Arm;

fn main() {}
