use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
// No #[dynamics(...)] at all.
struct Arm;

fn main() {}
