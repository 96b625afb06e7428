//! Linearising a model-predictive controller's horizon in one call: the Franka Panda (from its
//! URDF) along 100 knots of a reference motion, `∂q̈/∂q`, `∂q̈/∂q̇` and `M⁻¹` at every knot from
//! `forward_dynamics_derivatives_batch`, the continuous-time `A = [[0, I], [∂q̈/∂q, ∂q̈/∂q̇]]`
//! and `B = [[0], [M⁻¹]]` a solver discretises; the same knots one call at a time beside it.
//!
//! ```text
//! cargo run --release -p dynamics-examples --example horizon_panda
//! ```
//!
//! It fails if a knot's batch result differs from its own call's by one bit. The times it
//! prints are one run's (the median of 51 repeats), not a benchmark (`bench/run` has those).

use dynamics_runtime::{Dynamics, DynamicsBatch, DynamicsDerivatives, DynamicsDerivativesBatch};
use std::hint::black_box;
use std::time::Instant;

/// The Panda, from the vendor's URDF, with the derivatives.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/panda.urdf",
    base = "panda_link0",
    tip = "panda_link8",
    derivatives = true
)]
struct Panda;

const KNOTS: usize = 100;
/// The horizon's length, s.
const HORIZON_S: f64 = 1.0;

/// The reference motion at time `t`: each joint a sinusoid about a bent pose.
fn reference(t: f64) -> [[f64; 7]; 3] {
    let home = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
    let mut state = [[0.0; 7]; 3];
    for (j, &h) in home.iter().enumerate() {
        let (a, w) = (0.3 / (1.0 + j as f64), 2.0 + 0.5 * j as f64);
        let (s, c) = (w * t).sin_cos();
        state[0][j] = h + a * s;
        state[1][j] = a * w * c;
        state[2][j] = -a * w * w * s;
    }
    state
}

/// The median of `f`'s times over 51 runs, in ns.
fn median_ns(mut f: impl FnMut()) -> f64 {
    let mut ns: Vec<f64> = (0..51)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e9
        })
        .collect();
    ns.sort_by(f64::total_cmp);
    ns[ns.len() / 2]
}

fn main() {
    let robot = Panda;
    // The knots and the torques that follow the reference: τ = M q̈ + C q̇ + g at each.
    let knots: Vec<[[f64; 7]; 3]> = (0..KNOTS)
        .map(|k| reference(HORIZON_S * k as f64 / KNOTS as f64))
        .collect();
    let q: Vec<[f64; 7]> = knots.iter().map(|s| s[0]).collect();
    let qd: Vec<[f64; 7]> = knots.iter().map(|s| s[1]).collect();
    let qdd: Vec<[f64; 7]> = knots.iter().map(|s| s[2]).collect();
    let mut tau = vec![[0.0; 7]; KNOTS];
    robot.inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);

    // One call for the horizon.
    let zero = robot.forward_dynamics_derivatives(&q[0], &qd[0], &tau[0]);
    let mut batch = vec![zero; KNOTS];
    let batch_ns = median_ns(|| {
        robot.forward_dynamics_derivatives_batch(&q[..], &qd[..], &tau[..], &mut batch[..]);
        black_box(&batch);
    });
    // One call per knot.
    let mut single = vec![zero; KNOTS];
    let single_ns = median_ns(|| {
        for (k, out) in single.iter_mut().enumerate() {
            *out = robot.forward_dynamics_derivatives(black_box(&q[k]), &qd[k], &tau[k]);
        }
        black_box(&single);
    });

    for (k, (b, s)) in batch.iter().zip(&single).enumerate() {
        let (b, s) = (
            b.as_ref().expect("M is positive definite"),
            s.as_ref().unwrap(),
        );
        let bits = |m: &[[f64; 7]; 7]| m.iter().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
        for (x, y) in [
            (&b.dqdd_dq, &s.dqdd_dq),
            (&b.dqdd_dqd, &s.dqdd_dqd),
            (&b.dqdd_dtau, &s.dqdd_dtau),
        ] {
            assert_eq!(
                bits(x),
                bits(y),
                "knot {k}: the batch differs from one call"
            );
        }
        // The reference is followed: q̈ from the torques is the reference's.
        let err = (0..7)
            .map(|j| (b.qdd[j] - qdd[k][j]).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-9, "knot {k}: q̈ off by {err:e}");
    }

    let last = batch[KNOTS - 1].as_ref().unwrap();
    println!("The Franka Panda, {KNOTS} knots over {HORIZON_S} s, linearised: A = [[0, I], [∂q̈/∂q, ∂q̈/∂q̇]], B = [[0], [M⁻¹]]");
    println!(
        "  last knot: ∂q̈1/∂q2 = {:+.4}, ∂q̈4/∂q̇4 = {:+.4}, (M⁻¹)77 = {:.3}",
        last.dqdd_dq[0][1], last.dqdd_dqd[3][3], last.dqdd_dtau[6][6]
    );
    println!(
        "  one batch call:     {:8.1} ns per knot",
        batch_ns / KNOTS as f64
    );
    println!(
        "  one call per knot:  {:8.1} ns per knot",
        single_ns / KNOTS as f64
    );
    println!("  (this run's medians of 51; every knot's batch result equal to its own call's, bit for bit)");
}
