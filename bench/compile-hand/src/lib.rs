//! The 16-joint Allegro right hand (four fingers of four joints: a tree) from its URDF, every
//! generated method of the dynamics, forward dynamics and derivatives instantiated in `f64` and
//! `f32`: the compile-time case of issue 41 (a 16-joint hand with the derivatives), timed by
//! `bench/compile-time`.
use dynamics_runtime::{Dynamics, DynamicsDerivatives, Real};

/// The hand, every joint below the palm; its published inertias break the triangle inequality.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../robots/urdf/trees/allegro_right_hand.urdf",
    base = "palm_link",
    check_inertia = false,
    derivatives = true
)]
pub struct Hand;

/// Joints of the hand.
const N: usize = 16;

/// Every method of `r` at one state, summed so that none is optimized away.
fn all<R: DynamicsDerivatives<N>, T: Real>(r: &R, q: &[T; N], qd: &[T; N], qdd: &[T; N]) -> T {
    let tau = r.inverse_dynamics(q, qd, qdd);
    let m = r.mass_matrix(q);
    let c = r.coriolis_matrix(q, qd);
    let g = r.gravity_torques(q);
    let h = r.bias_torques(q, qd);
    let cqd = r.coriolis_torques(q, qd);
    let mut sum = r.kinetic_energy(q, qd) + r.potential_energy(q);
    for i in 0..N {
        sum += tau[i] + m[i][i] + c[i][0] + g[i] + h[i] + cqd[i];
    }
    let forward = (r.forward_dynamics(q, qd, &tau), r.mass_matrix_inverse(q));
    if let (Ok(qdd), Ok(inverse)) = forward {
        for i in 0..N {
            sum += qdd[i] + inverse[i][i];
        }
    }
    let inverse = r.inverse_dynamics_derivatives(q, qd, qdd);
    for i in 0..N {
        sum += inverse.dtau_dq[i][0] + inverse.dtau_dqd[i][0];
    }
    if let Ok(forward) = r.forward_dynamics_derivatives(q, qd, &tau) {
        for i in 0..N {
            sum += forward.dqdd_dq[i][0] + forward.dqdd_dqd[i][0] + forward.dqdd_dtau[i][0];
        }
    }
    sum
}

/// The hand in `f64`.
pub fn f64s(hand: &Hand, q: &[f64; N], qd: &[f64; N], qdd: &[f64; N]) -> f64 {
    all(hand, q, qd, qdd)
}

/// The hand in `f32`.
pub fn f32s(hand: &Hand, q: &[f32; N], qd: &[f32; N], qdd: &[f32; N]) -> f32 {
    all(hand, q, qd, qdd)
}
