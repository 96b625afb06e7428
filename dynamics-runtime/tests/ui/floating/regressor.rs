use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
// A floating base has M, h, τ and g only, for now: the derivatives are refused, not wrong.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../../../robots/urdf/floating/solo12.urdf",
    base = floating,
    derivatives = true
)]
struct Solo;

fn main() {}
