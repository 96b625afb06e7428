use dynamics_runtime::{Dynamics, DynamicsSimplified};

// A struct field has no bound over the envelope: refused, and the trait's methods still
// there, so that calling them adds no errors of their own.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 1, 0]],
    link(mass = payload, com = [-0.5, 0, 0]),
    simplify(tolerance = 0.1),
)]
struct Arm {
    payload: f64,
}

fn main() {
    let _ = Arm { payload: 1.0 }.inverse_dynamics_simplified(&[0.0], &[0.0], &[0.0]);
}
