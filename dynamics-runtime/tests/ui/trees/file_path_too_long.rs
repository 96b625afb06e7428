use dynamics_runtime::Dynamics;

// A description file of a tree whose first branch has 17 joints: refused at its seventeenth.
#[derive(Dynamics)]
#[dynamics(file = "path_too_long.toml")]
struct Arm;

fn main() {}
