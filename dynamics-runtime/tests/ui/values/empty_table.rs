use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [])]
struct Arm;

fn main() {}
