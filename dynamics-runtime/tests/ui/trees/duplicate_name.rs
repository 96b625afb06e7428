use dynamics_runtime::Dynamics;

// Two joints of one name.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(name = "palm"), revolute(name = "palm"), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
