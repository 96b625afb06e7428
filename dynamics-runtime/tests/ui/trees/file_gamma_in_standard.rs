use dynamics_runtime::Dynamics;

// A description file with γ in a standard table.
#[derive(Dynamics)]
#[dynamics(file = "gamma_in_standard.toml")]
struct Arm;

fn main() {}
