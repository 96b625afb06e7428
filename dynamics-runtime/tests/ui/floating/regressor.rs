use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
// A floating base has no regressor yet: it is refused, not wrong.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../../../robots/urdf/floating/solo12.urdf",
    base = floating,
    regressor = true
)]
struct Solo;

fn main() {}
