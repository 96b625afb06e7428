use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 2m, 0]], link(mass = 1))]
struct Arm;

fn main() {}
