use dynamics_runtime::Dynamics;

// A mistake in the table: the only error reported is that one, not the calls below.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, lenght, 0], [q, 0, 1, 0]], link(mass = 1), link(mass = 1))]
struct Arm {
    length: f64,
}

fn main() {
    let arm = Arm { length: 1.0 };
    let _ = arm.length;
    let tau = arm.inverse_dynamics(&[0.0; 2], &[0.0; 2], &[0.0; 2]);
    let m = arm.mass_matrix(&[0.0f32; 2]);
    let _ = (tau, m);
}
