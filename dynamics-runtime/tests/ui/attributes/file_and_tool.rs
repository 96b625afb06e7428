use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(file = "../files/two_link.toml", tool = [0, 0, 0.1, 0, 0, 0])]
struct Arm;

fn main() {}
