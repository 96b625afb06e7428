use dynamics_runtime::Dynamics;

// A parent named by a name no joint has.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(name = "palm"), revolute(parent = "plam"), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
