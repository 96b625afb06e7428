use dynamics_runtime::Dynamics;

// No field can be named `Self` (nor `r#Self`): the value that names it is refused on the token.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 2 * Self, 0]], link(mass = 1))]
struct Arm {
    length: f64,
}

fn main() {}
