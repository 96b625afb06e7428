//! Forward dynamics and `M⁻¹` (the LDLᵀ of M):
//!
//! * on the reference robots, compiled, in `f64` and `f32`: `forward_dynamics` of Pinocchio's
//!   τ (the data files' `tau` = `rnea(q, q̇, q̈)`) is the sample's q̈; the round trip
//!   `forward_dynamics(q, q̇, inverse_dynamics(q, q̇, q̈)) = q̈`; `M · M⁻¹ = I`;
//! * against Pinocchio's `aba` and `computeMinverse` (`data/forward/`, made by its `make.py`)
//!   at 1e-10, f64;
//! * on random robots ([`dynamics_tests::random::case`]), the expression graph interpreted:
//!   the round trip, and `M⁻¹` equal to nalgebra's inverse of the reference's M;
//! * with friction: the round trip, and q̈ = M⁻¹(τ − C q̇ − g − f) with f by hand;
//! * the error: a robot whose parameters (struct fields) leave a joint with no inertia gets
//!   `Err(NotPositiveDefinite)`, not NaN, and so does a NaN angle that M depends on; the UR5
//!   of the reference data, whose last link has no inertia about its axis (Pinocchio's M has
//!   `M66 = 0`), gets it at every sample.

use dynamics_reference::nalgebra::DMatrix;
use dynamics_reference::scaled_error;
use dynamics_runtime::{Dynamics, NotPositiveDefinite};
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::case;
use dynamics_tests::reference::{flat, matrix, samples, samples_counted, vector};
use dynamics_tests::robots::{
    General, NikuPolar, NikuTwoLink, Panda, Puma560, Random1, Random2, Random5, Rubbing, Stanford,
    Tilted, Ur5, Ur5Urdf,
};
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestRunner};

/// Scaled tolerance in `f64`: the solves lose what M's condition number says.
const F64: f64 = 1e-10;
/// Scaled tolerance in `f32`.
const F32: f64 = 1e-4;

fn to_f32<const N: usize>(v: [f64; N]) -> [f32; N] {
    v.map(|x| x as f32)
}

/// The worst scaled error of `M M⁻¹ − I`.
fn identity_error<const N: usize>(m: &[[f64; N]; N], inverse: &[[f64; N]; N]) -> f64 {
    let product: Vec<f64> = (0..N * N)
        .map(|e| (0..N).map(|k| m[e / N][k] * inverse[k][e % N]).sum())
        .collect();
    let identity: Vec<f64> = (0..N * N).map(|e| f64::from(e / N == e % N)).collect();
    scaled_error(&product, &identity)
}

/// Every check on `robot` against every sample of `tests/data/<file>`; returns the worst
/// scaled errors in f64 and f32.
fn check<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) -> (f64, f64) {
    let (mut worst64, mut worst32) = (0.0f64, 0.0f64);
    for s in samples(file) {
        let (q, qd, qdd, tau) = (
            vector::<N>(&s["q"]),
            vector::<N>(&s["qd"]),
            vector::<N>(&s["qdd"]),
            vector::<N>(&s["tau"]),
        );
        let from_pinocchio = robot.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
        let round_trip = robot
            .forward_dynamics(&q, &qd, &robot.inverse_dynamics(&q, &qd, &qdd))
            .expect("M ≻ 0");
        let inverse = robot.mass_matrix_inverse(&q).expect("M ≻ 0");
        let m = matrix::<N>(&s["M"]);
        worst64 = worst64
            .max(scaled_error(&from_pinocchio, &qdd))
            .max(scaled_error(&round_trip, &qdd))
            .max(identity_error(&m, &inverse));
        let (q, qd) = (to_f32(q), to_f32(qd));
        let tau = robot.inverse_dynamics(&q, &qd, &to_f32(qdd));
        let qdd32 = robot.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
        let inverse = robot.mass_matrix_inverse(&q).expect("M ≻ 0");
        worst32 = worst32
            .max(scaled_error(&qdd32.map(f64::from), &qdd))
            .max(identity_error(&m, &inverse.map(|r| r.map(f64::from))));
    }
    println!("{file}: f64 {worst64:.1e}, f32 {worst32:.1e}");
    assert!(worst64 < F64, "{file}: f64 error {worst64:e}");
    assert!(worst32 < F32, "{file}: f32 error {worst32:e}");
    (worst64, worst32)
}

#[test]
fn reference_robots() {
    check(&Puma560, "reference/data/puma560.json");
    check(&Stanford, "reference/data/stanford.json");
    check(&Ur5Urdf, "frames/ur5_urdf.json");
    check(&Tilted, "frames/tilted.json");
    check(&NikuTwoLink, "reference/data/niku_2link.json");
    check(&NikuPolar, "reference/data/niku_polar.json");
    check(&Random1, "reference/data/random1.json");
    check(&Random2, "reference/data/random2.json");
    check(&Random5, "reference/data/random5.json");
    check(&Panda, "panda/data.json");
    check(&General, "frames/general.json");
}

/// `forward_dynamics` and `mass_matrix_inverse` against `data/forward/<name>.json`; returns
/// the worst scaled error.
fn against_pinocchio<R: Dynamics<N>, const N: usize>(robot: &R, name: &str) -> f64 {
    let mut worst = 0.0f64;
    for s in samples_counted(&format!("forward/{name}.json"), 10) {
        let (q, qd, tau) = (
            vector::<N>(&s["q"]),
            vector::<N>(&s["qd"]),
            vector::<N>(&s["tau"]),
        );
        let qdd = robot.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
        let inverse = robot.mass_matrix_inverse(&q).expect("M ≻ 0");
        worst = worst
            .max(scaled_error(&qdd, &vector::<N>(&s["qdd"])))
            .max(scaled_error(&flat(inverse), &flat(matrix::<N>(&s["Minv"]))));
    }
    println!("forward/{name}: {worst:.1e}");
    assert!(worst < 1e-10, "{name}: {worst:e}");
    worst
}

#[test]
fn pinocchio_aba_and_minverse() {
    dynamics_tests::for_each_robot_with_forward_data!(against_pinocchio);
}

#[test]
fn ur5_reference_model_is_singular() {
    for s in samples("reference/data/ur5.json") {
        let (q, qd, tau) = (
            vector::<6>(&s["q"]),
            vector::<6>(&s["qd"]),
            vector::<6>(&s["tau"]),
        );
        assert_eq!(matrix::<6>(&s["M"])[5][5], 0.0);
        assert_eq!(
            Ur5.forward_dynamics(&q, &qd, &tau),
            Err(NotPositiveDefinite)
        );
        assert_eq!(Ur5.mass_matrix_inverse(&q), Err(NotPositiveDefinite));
        assert_eq!(
            Ur5.mass_matrix_inverse(&to_f32(q)),
            Err(NotPositiveDefinite)
        );
    }
}

/// A two-link planar arm with point masses `m1`, `m2` at the link tips: M is singular where
/// `m2 = 0` (joint 2 then moves nothing).
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = m1),
    link(mass = m2),
)]
struct PointMasses {
    m1: f64,
    m2: f64,
}

#[test]
fn not_positive_definite_is_an_error() {
    let (q, qd, tau): ([f64; 2], [f64; 2], [f64; 2]) = ([0.3, -0.4], [0.1, 0.2], [1.0, 2.0]);
    let arm = PointMasses { m1: 2.0, m2: 1.0 };
    assert!(arm.forward_dynamics(&q, &qd, &tau).is_ok());
    // By hand, the point masses: M = [[m1 l1² + m2 |p2|², m2 (l2² + l1 l2 c2)], [·, m2 l2²]].
    let c2 = q[1].cos();
    let m = [
        [
            2.0 * 0.49 + 1.0 * (0.49 + 0.25 + 0.7 * c2),
            0.25 + 0.35 * c2,
        ],
        [0.25 + 0.35 * c2, 0.25],
    ];
    let inverse = arm.mass_matrix_inverse(&q).expect("M ≻ 0");
    assert!(identity_error(&m, &inverse) < 1e-14);
    let limp = PointMasses { m1: 2.0, m2: 0.0 };
    assert_eq!(
        limp.forward_dynamics(&q, &qd, &tau),
        Err(NotPositiveDefinite)
    );
    assert_eq!(limp.mass_matrix_inverse(&q), Err(NotPositiveDefinite));
    assert_eq!(
        limp.forward_dynamics(&to_f32(q), &to_f32(qd), &to_f32(tau)),
        Err(NotPositiveDefinite)
    );
    // M depends on q2 alone: a NaN there reaches the pivots.
    let negative = PointMasses { m1: -2.0, m2: 1.0 };
    assert_eq!(negative.mass_matrix_inverse(&q), Err(NotPositiveDefinite));
    assert_eq!(
        arm.forward_dynamics(&[0.0, f64::NAN], &qd, &tau),
        Err(NotPositiveDefinite)
    );
    assert_eq!(
        NotPositiveDefinite.to_string(),
        "the mass matrix is not positive definite at this configuration"
    );
}

#[test]
fn friction_enters_as_in_inverse_dynamics() {
    let arm = Rubbing {
        fv2: 0.1,
        eps: 0.05,
    };
    let (q, qd, qdd) = ([0.4, -1.1], [0.7, -0.02], [1.5, -0.6]);
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let back = arm.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
    assert!(scaled_error(&back, &qdd) < 1e-13, "{back:?}");
    // q̈ = M⁻¹(τ − h − f), f by hand, M⁻¹ by nalgebra.
    let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
    let f = [
        0.3 * qd[0] + 1.5 * sign(qd[0]) - 0.2,
        0.1 * qd[1] + 0.8 * (qd[1] / 0.05).tanh(),
    ];
    let h = arm.bias_torques(&q, &qd);
    let m = arm.mass_matrix(&q);
    let inverse = DMatrix::from_fn(2, 2, |i, j| m[i][j])
        .try_inverse()
        .expect("M ≻ 0");
    let tau = [1.0, -0.5];
    let expected: Vec<f64> = (0..2)
        .map(|i| {
            (0..2)
                .map(|j| inverse[(i, j)] * (tau[j] - h[j] - f[j]))
                .sum()
        })
        .collect();
    let qdd = arm.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
    assert!(
        scaled_error(&qdd, &expected) < 1e-13,
        "{qdd:?} vs {expected:?}"
    );
}

/// Random robots, the graph interpreted: the round trip through τ, and M⁻¹ against
/// nalgebra's inverse of the reference's (the textbook's O(n⁴) trace method) M.
#[test]
fn random_robots() {
    let config = Config {
        cases: 64,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(18),
        ..Config::default()
    };
    let result = TestRunner::new(config).run(&case(), |c| {
        let eq = dynamics_codegen::derive(&c.robot.model());
        let n = eq.dof;
        let at = |tau: &[f64]| {
            let state = State {
                q: &c.q,
                qd: &c.qd,
                qdd: &c.qdd,
                tau,
            };
            evaluate(&eq, state)
        };
        let values = at(&vec![0.0; n]);
        let tau: Vec<f64> = eq.tau.iter().map(|id| values[id.index()]).collect();
        let values = at(&tau);
        let pivots_positive = eq
            .forward
            .factors
            .pivots
            .iter()
            .all(|id| values[id.index()] > 0.0);
        proptest::prop_assert!(pivots_positive);
        let qdd: Vec<f64> = eq.forward.qdd.iter().map(|id| values[id.index()]).collect();
        let reference = c.robot.reference();
        let m = reference.mass_matrix(&c.q);
        // The solve loses up to M's condition number.
        let condition = m.norm() * m.clone().try_inverse().map_or(f64::INFINITY, |i| i.norm());
        let tolerance = 1e-13 * condition.max(1.0);
        let error = scaled_error(&qdd, &c.qdd);
        proptest::prop_assert!(error < tolerance, "q̈ error {error:e}, cond {condition:e}");
        let inverse = m.try_inverse().expect("M ≻ 0");
        let generated: Vec<f64> = eq
            .forward
            .mass_inverse
            .iter()
            .flatten()
            .map(|id| values[id.index()])
            .collect();
        let expected: Vec<f64> = (0..n * n).map(|e| inverse[(e / n, e % n)]).collect();
        let error = scaled_error(&generated, &expected);
        proptest::prop_assert!(error < tolerance, "M⁻¹ error {error:e}, cond {condition:e}");
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}
