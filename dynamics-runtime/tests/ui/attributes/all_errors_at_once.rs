use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, lenght, 0], [q, 0, 1, 0]], link(mass = -1), link(mas = 1), colour = red)]
struct Arm {
    length: f64,
}

fn main() {}
