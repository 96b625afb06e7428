use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
// Talos's joints have friction, for which a floating base's regressor has no columns yet:
// refused, not wrong (its derivatives model friction).
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../../../robots/urdf/floating/talos_reduced.urdf",
    base = floating,
    regressor = true
)]
struct Talos;

fn main() {}
