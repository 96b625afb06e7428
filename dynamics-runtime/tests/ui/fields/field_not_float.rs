use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = m))]
struct Arm {
    m: u32,
}

fn main() {}
