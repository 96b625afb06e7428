// A planar two-link arm (Niku, Example 6.4): rods of length l1, l2 and mass m1, m2 whose
// centres of mass are at mid-length, moving in a vertical plane.
use dynamics_runtime::Dynamics;

#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ    d    a     α
        [   q,   0,   l1,   0 ],
        [   q,   0,   l2,   0 ],
    ],
    link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0, m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0]),
    link(mass = m2, com = [-l2 / 2, 0, 0], inertia = [0, m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0]),
)]
struct TwoLink {
    l1: f64,
    l2: f64,
    m1: f64,
    m2: f64,
    g: f64,
}

fn main() {
    let arm = TwoLink {
        l1: 1.0,
        l2: 0.8,
        m1: 2.0,
        m2: 1.5,
        g: 9.81,
    };
    let q = [0.3, -0.5];
    let tau = arm.inverse_dynamics(&q, &[0.1, 0.2], &[1.0, -1.0]);
    // Holding the arm still takes exactly the gravity torques.
    assert_eq!(
        arm.inverse_dynamics(&q, &[0.0; 2], &[0.0; 2]),
        arm.gravity_torques(&q)
    );
    let m = arm.mass_matrix(&q);
    assert_eq!(m[0][1], m[1][0]);
    // The same robot in single precision, for an FPU without doubles.
    let tau32 = arm.inverse_dynamics(&[0.3f32, -0.5], &[0.1, 0.2], &[1.0, -1.0]);
    assert!((f64::from(tau32[0]) - tau[0]).abs() < 1e-4);
    println!("tau = {tau:?}");
}
