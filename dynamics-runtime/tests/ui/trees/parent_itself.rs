use dynamics_runtime::Dynamics;

// A joint that hangs from itself: a cycle.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(parent = 2), revolute()], link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
