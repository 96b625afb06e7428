use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(file = "../files/two_link.toml", tip = "tool0")]
struct Arm;

fn main() {}
