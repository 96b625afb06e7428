use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(dh = [[q, 0, 1, 0]], link(mass = 1))]
struct Arm;

fn main() {}
