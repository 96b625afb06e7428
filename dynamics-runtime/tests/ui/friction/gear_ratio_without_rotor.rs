use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1, gear_ratio = 100))]
struct Arm;

fn main() {}
