use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
// Talos's joints have friction, which a floating base's derivatives do not model yet: refused,
// not wrong.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../../../robots/urdf/floating/talos_reduced.urdf",
    base = floating,
    derivatives = true
)]
struct Talos;

fn main() {}
