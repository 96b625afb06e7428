//! Energy conservation of the generated forward dynamics: a robot released from rest under
//! gravity, no friction and no torque, keeps `E = T + V` (`kinetic_energy` +
//! `potential_energy`) constant; integrated with the classical fourth-order Runge-Kutta step,
//! the energy drifts by the integrator's error alone, `O(h⁴)` over a fixed time.
//!
//! The energy is an independent check of `forward_dynamics`: `T = ½ q̇ᵀ M q̇` and `V` are
//! summed link by link (eq. 6.39 and the links' heights), not through M's factorization, and
//! `dE/dt = q̇ᵀ (M q̈ + C q̇ + g) = q̇ᵀ τ` holds only for the true q̈ (with `Ṁ − 2C` skew). A
//! wrong q̈ (a missing Coriolis term, a wrong entry of M⁻¹) makes E drift at a rate that does
//! not shrink with the step; a right one makes the drift fall 16-fold when h is halved.

use dynamics_runtime::Dynamics;
use dynamics_tests::robots::{Panda, Puma560};

/// The state's derivative `(q̇, q̈)` at zero torque.
fn derivative<R: Dynamics<N>, const N: usize>(
    robot: &R,
    q: &[f64; N],
    qd: &[f64; N],
) -> ([f64; N], [f64; N]) {
    let qdd = robot
        .forward_dynamics(q, qd, &[0.0; N])
        .expect("M is positive definite along the motion");
    (*qd, qdd)
}

/// `x + h k`, elementwise.
fn step<const N: usize>(x: &[f64; N], h: f64, k: &[f64; N]) -> [f64; N] {
    core::array::from_fn(|i| h.mul_add(k[i], x[i]))
}

/// One classical Runge-Kutta step of `h` from `(q, q̇)`.
fn rk4<R: Dynamics<N>, const N: usize>(
    robot: &R,
    q: &[f64; N],
    qd: &[f64; N],
    h: f64,
) -> ([f64; N], [f64; N]) {
    let (dq1, dqd1) = derivative(robot, q, qd);
    let (dq2, dqd2) = derivative(robot, &step(q, h / 2.0, &dq1), &step(qd, h / 2.0, &dqd1));
    let (dq3, dqd3) = derivative(robot, &step(q, h / 2.0, &dq2), &step(qd, h / 2.0, &dqd2));
    let (dq4, dqd4) = derivative(robot, &step(q, h, &dq3), &step(qd, h, &dqd3));
    let combine = |x: &[f64; N], k: [&[f64; N]; 4]| -> [f64; N] {
        core::array::from_fn(|i| {
            x[i] + h / 6.0 * (k[0][i] + 2.0 * k[1][i] + 2.0 * k[2][i] + k[3][i])
        })
    };
    (
        combine(q, [&dq1, &dq2, &dq3, &dq4]),
        combine(qd, [&dqd1, &dqd2, &dqd3, &dqd4]),
    )
}

/// What a run measured.
struct Run {
    /// The largest `|E(t) − E(0)|` over the motion divided by the largest kinetic energy
    /// reached (the energy that changed form, the scale of the motion).
    drift: f64,
    /// The largest joint speed reached, rad/s: the motion's fastest rate.
    speed: f64,
}

/// Released from rest at `q0`, integrated for `duration` seconds in steps of `h`.
fn release<R: Dynamics<N>, const N: usize>(robot: &R, q0: [f64; N], duration: f64, h: f64) -> Run {
    let energy =
        |q: &[f64; N], qd: &[f64; N]| robot.kinetic_energy(q, qd) + robot.potential_energy(q);
    let (mut q, mut qd) = (q0, [0.0; N]);
    let start = energy(&q, &qd);
    let (mut drift, mut kinetic, mut speed) = (0.0f64, 0.0f64, 0.0f64);
    let steps = (duration / h).round() as usize;
    for _ in 0..steps {
        (q, qd) = rk4(robot, &q, &qd, h);
        drift = drift.max((energy(&q, &qd) - start).abs());
        kinetic = kinetic.max(robot.kinetic_energy(&q, &qd));
        speed = qd.iter().fold(speed, |s, x| s.max(x.abs()));
    }
    // Released away from equilibrium, the robot falls and swings: several joules change form.
    assert!(kinetic > 1.0, "the robot barely moved: {kinetic} J");
    Run {
        drift: drift / kinetic,
        speed,
    }
}

/// Three seconds of simulated time at h = 2 ms and 1 ms. RK4's error over a fixed time is
/// `C h⁴` (local error `O(h⁵)` per step, `1/h` steps): with ω the fastest joint speed reached
/// (tens of rad/s here: the light wrists spin), its scale is `(ω h)⁴`, the bound on the
/// relative drift at 1 ms (1e-5 for 56 rad/s). And the drift must fall as `h⁴`, 16-fold from
/// 2 ms to 1 ms (12 to 20 allowed): an error in q̈ drifts E at a rate independent of h,
/// which a q̈ off by one part in a million already shows (the ratio falls to about 1).
fn check<R: Dynamics<N>, const N: usize>(robot: &R, name: &str, q0: [f64; N]) {
    let (h, duration) = (1e-3, 3.0);
    let coarse = release(robot, q0, duration, 2.0 * h);
    let fine = release(robot, q0, duration, h);
    let bound = (fine.speed * h).powi(4);
    let ratio = coarse.drift / fine.drift;
    println!(
        "{name}: relative drift {:.1e} (h = 2 ms), {:.1e} (1 ms, bound {bound:.1e}), ratio {ratio:.1}, fastest joint {:.0} rad/s",
        coarse.drift, fine.drift, fine.speed
    );
    assert!(
        fine.drift < bound,
        "{name}: drift {:e} ≥ {bound:e}",
        fine.drift
    );
    assert!(
        (12.0..20.0).contains(&ratio),
        "{name}: the drift is not O(h⁴): ratio {ratio}"
    );
}

#[test]
fn puma560_released_from_rest() {
    check(&Puma560, "puma560", [0.3, -0.4, 0.2, 0.5, 1.0, -0.7]);
}

#[test]
fn panda_released_from_rest() {
    check(&Panda, "panda", [0.2, 0.9, -0.3, -1.2, 0.5, 1.6, 0.4]);
}
