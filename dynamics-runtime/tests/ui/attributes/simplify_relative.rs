use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 1, 0]],
    link(mass = 1, com = [-0.5, 0, 0]),
    simplify(rated = [-10], qdd_max = 5),
)]
struct Arm;

fn main() {}
