use dynamics_runtime::Dynamics;

// A description file whose joint names a later parent.
#[derive(Dynamics)]
#[dynamics(file = "parent_later.toml")]
struct Arm;

fn main() {}
