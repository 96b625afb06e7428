use dynamics_runtime::Dynamics;

// The D-H table needs the placement's angles as numbers.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    joints = [revolute(rpy = [0, tilt, 0], axis = [0, 0, 1])],
    link(mass = 1),
)]
struct Arm {
    tilt: f64,
}

fn main() {}
