use dynamics_runtime::{Dynamics, DynamicsBaseParameters, DynamicsRegressor};

// The regressor takes any field; the base parameters' grouping depends on the lengths.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [[q, 0, length, 0], [q, 0, 0.5, 0]],
    link(mass = 1),
    link(mass = mass),
    regressor = true,
    base_parameters = true
)]
struct Arm {
    length: f64,
    mass: f64,
}

fn main() {
    let arm = Arm { length: 1.0, mass: 2.0 };
    let _ = arm.regressor(&[0.0; 2], &[0.0; 2], &[0.0; 2]);
    let _: [f64; 3] = arm.base_parameters();
}
