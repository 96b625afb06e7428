use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(file = "../../../../tests/tests/ui/files/two_link.toml", tip = "tool0")]
struct Arm;

fn main() {}
