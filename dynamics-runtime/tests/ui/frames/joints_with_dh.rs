use dynamics_runtime::Dynamics;

// A robot's joints are given one way: a D-H table or placements and axes.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    joints = [revolute(axis = [0, 0, 1])],
    dh = [[q, 0, 1, 0]],
    link(mass = 1),
)]
struct Arm;

fn main() {}
