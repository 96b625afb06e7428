use dynamics_runtime::Dynamics;

// The regressor of a robot with a mimic joint: traced, not generated yet (the trait's shape).
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], regressor = true, joints = [revolute(), revolute(xyz = [0.5, 0, 0]), revolute(xyz = [0.5, 0, 0], mimic = (joint = 2, offset = 0.1))], link(mass = 1, inertia = [0.1, 0.1, 0.1, 0, 0, 0]), link(mass = 1, inertia = [0.1, 0.1, 0.1, 0, 0, 0]), link(mass = 1, inertia = [0.1, 0.1, 0.1, 0, 0, 0]))]
struct Arm;

fn main() {}
