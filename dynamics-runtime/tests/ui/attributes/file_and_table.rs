use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(file = "../files/two_link.toml", dh = [[q, 0, 1, 0]])]
struct Arm;

fn main() {}
