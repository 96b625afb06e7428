use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 1, 0], [q, 0, 1, 0]],
    link(mass = 1, com = [-0.5, 0, 0]),
    link(mass = 1, com = [-0.5, 0, 0]),
    simplify(tolerence = 1, q_min = [-1, -2, -3], qd_max = speed, q_max = [-2, 1]),
)]
struct Arm {
    speed: f64,
}

fn main() {}
