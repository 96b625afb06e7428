use dynamics_runtime::Dynamics;

// A parent declared after its child (a later one could close a cycle).
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(parent = 3), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
