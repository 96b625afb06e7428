use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(urdf = "robots/nowhere.urdf")]
struct Arm;

fn main() {}
