use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(
    urdf = "arm.urdf",
    dh = [[q, 0, 1, 0]],
)]
struct Arm;

fn main() {}
