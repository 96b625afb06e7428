use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
// A floating base has no tip kinematics (its frames are `FloatingKinematics`'): it is refused,
// not wrong.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../../../robots/urdf/floating/solo12.urdf",
    base = floating,
    tip_kinematics = true
)]
struct Solo;

fn main() {}
