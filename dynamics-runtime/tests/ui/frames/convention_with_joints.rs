use dynamics_runtime::Dynamics;

// `convention` is about D-H tables.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    convention = standard,
    joints = [revolute(axis = [0, 0, 1])],
    link(mass = 1),
)]
struct Arm;

fn main() {}
