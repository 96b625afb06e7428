use dynamics_runtime::Dynamics;

// `axes` for `axis`.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(axes = [0, 0, 1])], link(mass = 1))]
struct Arm;

fn main() {}
