use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, l, 0]], link(mass = 1))]
struct Arm(f64);

fn main() {}
