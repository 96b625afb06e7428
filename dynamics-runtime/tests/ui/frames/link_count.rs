use dynamics_runtime::Dynamics;

// Two joints, one link.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    joints = [revolute(), revolute(xyz = [1, 0, 0])],
    link(mass = 1),
)]
struct Arm;

fn main() {}
