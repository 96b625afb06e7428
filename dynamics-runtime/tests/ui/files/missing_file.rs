use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(file = "robots/nowhere.json")]
struct Arm;

fn main() {}
