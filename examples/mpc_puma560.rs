//! Model-predictive control of the PUMA 560 with the generated derivatives: at every control
//! period the dynamics are linearized at the measured state (`forward_dynamics_derivatives`:
//! `q̈`, `∂q̈/∂q`, `∂q̈/∂q̇`, `∂q̈/∂τ`), discretized with the semi-implicit Euler step
//! `q̇⁺ = q̇ + h q̈`, `q⁺ = q + h q̇⁺`, and a finite-horizon linear-quadratic regulator (the
//! Riccati recursion over the horizon, without constraints) gives the torques of the first
//! step, clipped to the motors' peak torques. The arm, simulated with `forward_dynamics` at a
//! finer step, moves from rest to a target pose and holds it against gravity with a payload.
//!
//! The time of the model is printed beside the solver's: the linearization is a small part of a
//! control period, the Riccati recursion over the horizon nearly all of it.
//!
//! Run with `cargo run --release -p dynamics-examples --example mpc_puma560`.

use dynamics_examples::Puma560;
use dynamics_runtime::nalgebra::DynamicsDerivativesNalgebra;
use dynamics_runtime::Dynamics;
use nalgebra::{SMatrix, SVector};
use std::ops::AddAssign;
use std::time::{Duration, Instant};

/// The state `[q; q̇]`, the input `τ`.
type State = SVector<f64, 12>;
type Input = SVector<f64, 6>;
type StateMatrix = SMatrix<f64, 12, 12>;
type InputMatrix = SMatrix<f64, 12, 6>;

/// The control period and the model's step, s.
const PERIOD: f64 = 0.01;
/// Steps of the horizon (0.3 s).
const HORIZON: usize = 30;
/// Simulation steps per control period.
const SUBSTEPS: usize = 10;
/// The motors' peak torques, N·m (Corke's Robotics Toolbox): the regulator does not know
/// them, the torques sent are clipped to them.
const PEAK_TORQUE: [f64; 6] = [97.6, 186.4, 89.4, 24.2, 20.1, 21.3];

/// One linearization of the discrete dynamics, `x⁺ ≈ x₀⁺ + F (x − x₀) + G (τ − τ₀)`.
struct Linear {
    next: State,
    f: StateMatrix,
    g: InputMatrix,
}

/// The semi-implicit Euler step of the arm at `(x0, tau0)` and its derivatives: with `A_q`,
/// `A_v`, `B` the derivatives of `q̈`, the velocity's rows are `[hA_q, I + hA_v]` and `hB`, and
/// the position's, `q⁺ = q + h q̇⁺`, are `[I, 0]` plus `h` times those.
fn linearize(robot: &Puma560, x0: &State, tau0: &Input) -> Linear {
    let (q, qd) = (x0.fixed_rows::<6>(0).into(), x0.fixed_rows::<6>(6).into());
    let d = robot
        .forward_dynamics_derivatives_na(&q, &qd, tau0)
        .expect("M(q) is positive definite");
    let h = PERIOD;
    let identity = SMatrix::<f64, 6, 6>::identity();
    let qd_next = qd + d.qdd * h;
    let mut next = State::zeros();
    next.fixed_rows_mut::<6>(0).copy_from(&(q + qd_next * h));
    next.fixed_rows_mut::<6>(6).copy_from(&qd_next);
    let (mut f, mut g) = (StateMatrix::zeros(), InputMatrix::zeros());
    f.fixed_view_mut::<6, 6>(6, 0).copy_from(&(d.dqdd_dq * h));
    f.fixed_view_mut::<6, 6>(6, 6)
        .copy_from(&(identity + d.dqdd_dqd * h));
    g.fixed_view_mut::<6, 6>(6, 0).copy_from(&(d.dqdd_dtau * h));
    let velocity_rows = (
        f.fixed_rows::<6>(6).into_owned(),
        g.fixed_rows::<6>(6).into_owned(),
    );
    f.fixed_rows_mut::<6>(0).copy_from(&(velocity_rows.0 * h));
    f.fixed_view_mut::<6, 6>(0, 0).add_assign(&identity);
    g.fixed_rows_mut::<6>(0).copy_from(&(velocity_rows.1 * h));
    Linear { next, f, g }
}

/// The regulator's weights: `Σ eᵀ Q e + vᵀ R v` over the horizon, in the deviations `e` from
/// the target state and `v` from the torques that hold it.
struct Weights {
    state: StateMatrix,
    input: SMatrix<f64, 6, 6>,
}

/// The first torques of the horizon's optimal sequence, with the dynamics of every step taken
/// as `model` (linearized at the current state `x0` and torques `tau0`), in deviations from the
/// target `(target, hold)`: `e⁺ = F e + G v + c`. Backward from the horizon's end, with the
/// value `½ eᵀ P e + pᵀ e`: `K = S⁻¹ GᵀPF`, `k = S⁻¹ Gᵀ(P c + p)`, `S = R + GᵀPG`, the
/// torques `v = −K e − k`.
fn first_torques(
    model: &Linear,
    weights: &Weights,
    (x0, tau0): (&State, &Input),
    (target, hold): (&State, &Input),
) -> Input {
    let (f, g, r) = (&model.f, &model.g, &weights.input);
    let c = model.next - target - f * (x0 - target) - g * (tau0 - hold);
    let (mut p_quadratic, mut p_linear) = (weights.state, State::zeros());
    let mut torques = Input::zeros();
    for _ in 0..HORIZON {
        let s = r + g.transpose() * p_quadratic * g;
        let s = s.cholesky().expect("R + GᵀPG is positive definite");
        let k_feedback = s.solve(&(g.transpose() * p_quadratic * f));
        let k_offset = s.solve(&(g.transpose() * (p_quadratic * c + p_linear)));
        let closed = f - g * k_feedback;
        p_linear = k_feedback.transpose() * r * k_offset
            + closed.transpose() * (p_quadratic * (c - g * k_offset) + p_linear);
        p_quadratic = weights.state
            + k_feedback.transpose() * r * k_feedback
            + closed.transpose() * p_quadratic * closed;
        p_quadratic = (p_quadratic + p_quadratic.transpose()) * 0.5;
        torques = hold - k_feedback * (x0 - target) - k_offset;
    }
    torques
}

fn main() {
    let robot = Puma560 { payload: 2.0 };
    let goal = [0.6, -0.4, 0.3, 0.5, -0.7, 0.9];
    let mut target = State::zeros();
    target
        .fixed_rows_mut::<6>(0)
        .copy_from(&SVector::from(goal));
    let hold = Input::from(robot.gravity_torques(&goal));
    let weights = Weights {
        state: StateMatrix::from_diagonal(&State::from_fn(|i, _| if i < 6 { 400.0 } else { 4.0 })),
        input: SMatrix::identity() * 1e-3,
    };
    let (mut q, mut qd) = ([0.0, -0.8, 0.6, 0.0, 0.0, 0.0], [0.0; 6]);
    let mut tau = Input::from(robot.gravity_torques(&q));
    let (mut modelling, mut solving) = (Duration::ZERO, Duration::ZERO);
    let periods = 200;
    let mut largest_error = f64::INFINITY;
    for k in 0..periods {
        let mut x = State::zeros();
        x.fixed_rows_mut::<6>(0).copy_from(&SVector::from(q));
        x.fixed_rows_mut::<6>(6).copy_from(&SVector::from(qd));
        let started = Instant::now();
        let model = linearize(&robot, &x, &tau);
        let linearized = Instant::now();
        tau = first_torques(&model, &weights, (&x, &tau), (&target, &hold))
            .zip_map(&Input::from(PEAK_TORQUE), |t, peak| t.clamp(-peak, peak));
        (modelling, solving) = (
            modelling + (linearized - started),
            solving + linearized.elapsed(),
        );
        largest_error = (0..6).fold(0.0f64, |m, i| m.max((q[i] - goal[i]).abs()));
        if k % 25 == 0 {
            println!(
                "t = {:.2} s  largest joint error {largest_error:.2e} rad  τ = {:.1?}",
                k as f64 * PERIOD,
                tau.as_slice()
            );
        }
        let applied: [f64; 6] = tau.into();
        robot.simulate(
            &mut q,
            &mut qd,
            &applied,
            PERIOD / SUBSTEPS as f64,
            SUBSTEPS,
        );
    }
    println!(
        "per control period: linearization {:.2} µs (forward_dynamics_derivatives and the \
         discrete step), Riccati recursion over {HORIZON} steps {:.1} µs",
        modelling.as_secs_f64() * 1e6 / f64::from(periods),
        solving.as_secs_f64() * 1e6 / f64::from(periods),
    );
    assert!(
        largest_error < 1e-3,
        "the arm should hold the target within a milliradian, not {largest_error:.1e} rad"
    );
}
