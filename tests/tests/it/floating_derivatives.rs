//! The first derivatives of robots on a free-flying base (`derivatives = true`): Solo 12,
//! ANYmal B and the Unitree G1 against Pinocchio 4.1's `computeRNEADerivatives` and
//! `computeABADerivatives` (`tests/data/floating/*_derivatives.json`, by `make.py`, which
//! checks them against central differences first), each matrix to 1e-12 scaled by its largest
//! element; the derivatives by `q` along the tangent (`integrate`), the base moved in its own
//! frame. And the batch form against one call per state.

use super::floating_base::{array, flat, numbers, reference, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{
    FloatingDynamicsDerivatives, FloatingDynamicsDerivativesBatch, NotPositiveDefinite,
};
use dynamics_tests::lanes::{close_values, routes_differ, Bits};

/// Solo 12 with its derivatives (apart from `floating_base.rs`' Solo 12, which the other
/// floating tests share without them).
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating,
    derivatives = true
)]
pub(super) struct Solo12;

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/anymal_b.urdf",
    base = floating,
    derivatives = true
)]
struct AnymalB;

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/g1_29dof.urdf",
    base = floating,
    derivatives = true
)]
struct G1;

fn flatten<const N: usize>(m: &[[f64; N]; N]) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

/// Every derivative of `robot` at every sample of `name`'s data, those of inverse dynamics to
/// [`TOLERANCE`], those of forward dynamics to `forward_tolerance`; the base position's columns
/// exactly zero, and the rotation's columns of `∂a/∂q` below the base's linear rows too.
/// Returns the largest errors of each.
pub(super) fn against_pinocchio<
    R: FloatingDynamicsDerivatives<Q, V>,
    const Q: usize,
    const V: usize,
>(
    robot: &R,
    name: &str,
    forward_tolerance: f64,
) -> [f64; 2] {
    let states = reference(name)["samples"].clone();
    let derivatives = reference(&format!("{name}_derivatives"));
    let samples = derivatives["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    let mut worst = [0.0_f64; 2];
    for (k, d) in samples.iter().enumerate() {
        let s = &states[k];
        let (q, v, a) = (
            array::<Q>(&s["q"]),
            array::<V>(&s["v"]),
            array::<V>(&s["a"]),
        );
        let tau = array::<V>(&d["tau_in"]);
        let inverse = robot.inverse_dynamics_derivatives(&q, &v, &a);
        let forward = robot
            .forward_dynamics_derivatives(&q, &v, &tau)
            .expect("M is positive definite");
        for (what, got, key) in [
            ("dtau_dq", flatten(&inverse.dtau_dq), "dtau_dq"),
            ("dtau_dv", flatten(&inverse.dtau_dqd), "dtau_dv"),
            ("a", forward.qdd.to_vec(), "ddq"),
            ("da_dq", flatten(&forward.dqdd_dq), "ddq_dq"),
            ("da_dv", flatten(&forward.dqdd_dqd), "ddq_dv"),
            ("da_dtau", flatten(&forward.dqdd_dtau), "ddq_dtau"),
        ] {
            let expected = if key == "ddq" {
                numbers(&d[key])
            } else {
                flat(&d[key])
            };
            let error = scaled_error(&got, &expected);
            let forward = usize::from(what.starts_with('a') || what.starts_with("da"));
            worst[forward] = worst[forward].max(error);
            let tolerance = [TOLERANCE, forward_tolerance][forward];
            assert!(
                error < tolerance,
                "{name} sample {k}: {what} off by {error:e}"
            );
        }
        for i in 0..V {
            for j in 0..3 {
                assert_eq!(inverse.dtau_dq[i][j], 0.0, "{name}: ∂τ_{i}/∂p_{j}");
                assert_eq!(forward.dqdd_dq[i][j], 0.0, "{name}: ∂a_{i}/∂p_{j}");
                if i >= 3 {
                    assert_eq!(forward.dqdd_dq[i][3 + j], 0.0, "{name}: ∂a_{i}/∂ω_{j}");
                }
            }
        }
    }
    worst
}

#[test]
fn solo12_against_pinocchio() {
    with_room(|| {
        let [inverse, forward] = against_pinocchio(&Solo12, "solo12", TOLERANCE);
        eprintln!("Solo 12: largest scaled errors ∂τ {inverse:e}, a and ∂a {forward:e}");
    });
}

/// ANYmal B: its legs in the file's order (the data permuted from Pinocchio's by name).
#[test]
fn anymal_b_against_pinocchio() {
    with_room(|| {
        let [inverse, forward] = against_pinocchio(&AnymalB, "anymal_b", TOLERANCE);
        eprintln!("ANYmal B: largest scaled errors ∂τ {inverse:e}, a and ∂a {forward:e}");
    });
}

/// The G1, 35 coordinates. Its M's condition number reaches 3.5e5 at these states (light
/// wrists beside a heavy trunk): Pinocchio's own `aba` misses `M a + h = τ` by up to 3.9e-12
/// (scaled), and a solve's error grows as the condition, 3.5e5 × 2.2e-16 ≈ 8e-11; so the forward
/// dynamics and its derivatives to 1e-10, `∂τ` to 1e-12.
#[test]
fn g1_against_pinocchio() {
    with_room(|| {
        let [inverse, forward] = against_pinocchio(&G1, "g1_29dof", 1e-10);
        eprintln!("G1: largest scaled errors ∂τ {inverse:e}, a and ∂a {forward:e}");
    });
}

/// Runs `f` on a thread with room for the derivatives unoptimized: on tangents in lanes
/// (AVX-512), one state's take more than a test thread's 2 MB of stack, as the lanes of eight
/// `f64` do.
pub(super) fn with_room(f: impl FnOnce() + Send) {
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(64 << 20)
            .spawn_scoped(s, f)
            .expect("a thread");
    });
}

/// The batch forms give each state's result: bit for bit where the lanes compute as one state
/// does, to rounding where one state's tangents are in lanes and the lane types' are not
/// (`routes_differ`); a state whose M is not positive definite (a NaN joint angle) is an error.
#[test]
fn batch_forms_agree_with_the_scalar_calls() {
    with_room(|| {
        let data = reference("solo12");
        let samples = data["samples"].as_array().expect("samples");
        let mut q: Vec<[f64; 19]> = samples.iter().map(|s| array(&s["q"])).collect();
        let v: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["v"])).collect();
        let a: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["a"])).collect();
        q[9][10] = f64::NAN;
        let mut inverse = vec![Solo12.inverse_dynamics_derivatives(&q[0], &v[0], &a[0]); q.len()];
        Solo12.inverse_dynamics_derivatives_batch(&q[..], &v[..], &a[..], &mut inverse[..]);
        let mut forward = vec![Solo12.forward_dynamics_derivatives(&q[0], &v[0], &a[0]); q.len()];
        Solo12.forward_dynamics_derivatives_batch(&q[..], &v[..], &a[..], &mut forward[..]);
        let differ = routes_differ::<dynamics_runtime::F64x4, 4>();
        for k in 0..q.len() {
            let what = format!("state {k}");
            let single = Solo12.inverse_dynamics_derivatives(&q[k], &v[k], &a[k]);
            if k != 9 {
                agree(differ, &what, &inverse[k], &single);
            }
            match (
                &forward[k],
                Solo12.forward_dynamics_derivatives(&q[k], &v[k], &a[k]),
            ) {
                (Ok(got), Ok(want)) => agree(differ, &what, got, &want),
                (Err(NotPositiveDefinite), Err(NotPositiveDefinite)) => assert_eq!(k, 9),
                (got, want) => panic!("{what}: {:?} against {:?}", got.is_ok(), want.is_ok()),
            }
        }
        assert!(forward[9].is_err());
    });
}

/// `got` as `want` bit for bit, or within 1e-9 (scaled) where the routes `differ`.
fn agree<X: Bits>(differ: bool, what: &str, got: &X, want: &X) {
    if differ {
        close_values(what, got, want, 1e-9);
    } else {
        let (mut x, mut y) = (Vec::new(), Vec::new());
        got.bits(&mut x);
        want.bits(&mut y);
        assert_eq!(x, y, "{what}");
    }
}
