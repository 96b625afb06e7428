use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1, rotor_inertia = 0.0001, gear_ratio = 0))]
struct Arm;

fn main() {}
