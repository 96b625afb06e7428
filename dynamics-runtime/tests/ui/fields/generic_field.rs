use dynamics_runtime::Dynamics;

// One error, on the field's use; none from the generated code about the name `T`.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, l1, 0]], link(mass = 1))]
struct Arm<T> {
    l1: T,
}

fn main() {}
