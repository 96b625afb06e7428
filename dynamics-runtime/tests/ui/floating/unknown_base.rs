use dynamics_runtime::Dynamics;

// The path is relative to this file: trybuild's crate, inside `target/`, has no such file.
#[derive(Dynamics)]
#[dynamics(urdf = "../../../../robots/urdf/floating/solo12.urdf", base = flying)]
struct Solo;

fn main() {}
