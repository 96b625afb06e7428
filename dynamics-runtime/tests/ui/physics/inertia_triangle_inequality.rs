use dynamics_runtime::Dynamics;

// PUMA 560 link 3 as published: 0.0125 + 0.066 < 0.086. `check_inertia = false` keeps it.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 1, 0]],
    link(mass = 4.8, inertia = [0.066, 0.086, 0.0125, 0, 0, 0]),
)]
struct Arm;

fn main() {}
