use dynamics_runtime::Dynamics;

// tips without a URDF.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 0, 0]], link(mass = 1), tips = ["hand"])]
struct Arm;

fn main() {}
