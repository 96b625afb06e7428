use dynamics_runtime::Dynamics;

// A tree whose first branch has 17 joints: refused at its seventeenth.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(), revolute(parent = 0)], link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1), link(mass = 1))]
struct Arm;

fn main() {}
