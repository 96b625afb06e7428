use dynamics_runtime::Dynamics;

// Parallel axes 1 and 2, the second offset by struct fields in two directions: the D-H table
// needs the offset's direction.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    joints = [revolute(), revolute(xyz = [lx, ly, 0])],
    link(mass = 1),
    link(mass = 1),
)]
struct Arm {
    lx: f64,
    ly: f64,
}

fn main() {}
