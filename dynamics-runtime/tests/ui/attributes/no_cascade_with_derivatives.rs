use dynamics_runtime::{Dynamics, DynamicsDerivatives};

// A mistake in the table of a robot that asks for its derivatives: the only error reported is
// that one, not the calls below.
#[derive(Dynamics)]
#[dynamics(derivatives = true, gravity = [0, 0, -9.81], dh = [[q, 0, lenght, 0]], link(mass = 1))]
struct Arm {
    length: f64,
}

fn main() {
    let arm = Arm { length: 1.0 };
    let _ = arm.length;
    let d = arm.inverse_dynamics_derivatives(&[0.0], &[0.0], &[0.0]);
    let f = arm.forward_dynamics_derivatives(&[0.0f32], &[0.0], &[0.0]);
    let _ = (d.dtau_dq, f.map(|f| f.qdd));
}
