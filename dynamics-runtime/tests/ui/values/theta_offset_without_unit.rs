use dynamics_runtime::Dynamics;

// The offset of `q` is an angle too.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q - 90, 0, 1, 0]], link(mass = 1))]
struct Arm;

fn main() {}
