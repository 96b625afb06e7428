use dynamics_runtime::Dynamics;

// rpy is in radians unless written with `deg`: 90 is almost surely a forgotten `deg`.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(rpy = [90, 0, 0])], link(mass = 1))]
struct Arm;

fn main() {}
