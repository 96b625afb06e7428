use dynamics_runtime::{Dynamics, DynamicsDerivatives};

// Without `derivatives = true` the robot has no `DynamicsDerivatives`: its code is not generated.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1))]
struct Arm;

fn main() {
    let _ = Arm.inverse_dynamics_derivatives(&[0.0], &[0.0], &[0.0]);
}
