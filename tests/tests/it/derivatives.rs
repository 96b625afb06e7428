//! The derivatives of the dynamics (`DynamicsDerivatives`, opt-in with `derivatives = true`):
//!
//! * against Pinocchio's `computeRNEADerivatives` and `computeABADerivatives`
//!   (`data/derivatives/`, made by its `make.py`) at 1e-10, f64, on every reference robot with
//!   a positive definite M;
//! * against central differences of the generated `inverse_dynamics` and `forward_dynamics`,
//!   on the same robots and on the friction arm (Coulomb smoothed on joint 2), in `f64`; `f32`
//!   against `f64`; on a tree of nine joints (the Panda with free fingers); ∂τ and ∂q̈ on
//!   Baxter with free fingers (19 joints, in lanes one function per arm, and per subtree for
//!   ∂q̈), and against the same states in `F64x4` (the columns one by one) to 1e-12;
//! * the friction arm's `∂τ/∂q̇` by hand: `2 C` plus the viscous slope, plus `f_c/ε sech²(q̇/ε)`
//!   where smoothed (the plain Coulomb step is flat away from 0);
//! * on random robots ([`dynamics_tests::random::case`]), the expression graph interpreted:
//!   `∂τ/∂q` and `∂τ/∂q̇` against central differences of the textbook's O(n⁴) method
//!   (`dynamics-reference`), an implementation that shares no code with the generator.

use dynamics_reference::scaled_error;
use dynamics_runtime::lanes::F64x4;
use dynamics_runtime::{Dynamics, DynamicsDerivatives, NotPositiveDefinite};
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::lanes::{close, routes_differ, same, Motion};
use dynamics_tests::random::case;
use dynamics_tests::reference::{flat, matrix, samples_counted, vector};
use dynamics_tests::robots::{NikuPolar, Panda, Puma560, Rubbing, Stanford};
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestRunner};

/// The step of the central differences.
const STEP: f64 = 1e-6;

/// Every derivative against Pinocchio's at every sample; returns the worst scaled error.
fn against_pinocchio<R: DynamicsDerivatives<N>, const N: usize>(robot: &R, name: &str) -> f64 {
    let mut worst = 0.0f64;
    for s in samples_counted(&format!("derivatives/{name}.json"), 10) {
        let [q, qd, qdd, tau] = ["q", "qd", "qdd", "tau"].map(|key| vector::<N>(&s[key]));
        let inverse = robot.inverse_dynamics_derivatives(&q, &qd, &qdd);
        let forward = robot
            .forward_dynamics_derivatives(&q, &qd, &tau)
            .expect("M ≻ 0");
        let expected = |key: &str| flat(matrix::<N>(&s[key]));
        worst = worst
            .max(scaled_error(&flat(inverse.dtau_dq), &expected("dtau_dq")))
            .max(scaled_error(&flat(inverse.dtau_dqd), &expected("dtau_dqd")))
            .max(scaled_error(&forward.qdd, &vector::<N>(&s["qdd_of_tau"])))
            .max(scaled_error(&flat(forward.dqdd_dq), &expected("dqdd_dq")))
            .max(scaled_error(&flat(forward.dqdd_dqd), &expected("dqdd_dqd")))
            .max(scaled_error(
                &flat(forward.dqdd_dtau),
                &expected("dqdd_dtau"),
            ));
    }
    println!("derivatives/{name}: {worst:.1e}");
    assert!(worst < 1e-10, "{name}: {worst:e}");
    worst
}

#[test]
fn pinocchio_rnea_and_aba_derivatives() {
    dynamics_tests::for_each_robot_with_forward_data!(against_pinocchio);
}

/// Column j of `∂f/∂x` by central differences at `x`: row i is `∂f_i/∂x_j`.
fn central<const N: usize>(x: [f64; N], f: impl Fn([f64; N]) -> [f64; N]) -> [[f64; N]; N] {
    let columns: [[f64; N]; N] = core::array::from_fn(|j| {
        let (mut up, mut down) = (x, x);
        up[j] += STEP;
        down[j] -= STEP;
        let (a, b) = (f(up), f(down));
        core::array::from_fn(|i| (a[i] - b[i]) / (2.0 * STEP))
    });
    core::array::from_fn(|i| core::array::from_fn(|j| columns[j][i]))
}

/// The worst scaled error of every derivative against central differences of the generated
/// `inverse_dynamics` and `forward_dynamics` at `(q, q̇, q̈)`, and of `f32` against `f64`.
fn against_differences<R: DynamicsDerivatives<N>, const N: usize>(
    robot: &R,
    [q, qd, qdd]: [[f64; N]; 3],
) -> (f64, f64) {
    let inverse = robot.inverse_dynamics_derivatives(&q, &qd, &qdd);
    let tau = robot.inverse_dynamics(&q, &qd, &qdd);
    let forward = robot
        .forward_dynamics_derivatives(&q, &qd, &tau)
        .expect("M ≻ 0");
    let fd = |q, qd, tau| robot.forward_dynamics(&q, &qd, &tau).expect("M ≻ 0");
    let pairs = [
        (
            inverse.dtau_dq,
            central(q, |x| robot.inverse_dynamics(&x, &qd, &qdd)),
        ),
        (
            inverse.dtau_dqd,
            central(qd, |x| robot.inverse_dynamics(&q, &x, &qdd)),
        ),
        (forward.dqdd_dq, central(q, |x| fd(x, qd, tau))),
        (forward.dqdd_dqd, central(qd, |x| fd(q, x, tau))),
        (forward.dqdd_dtau, central(tau, |x| fd(q, qd, x))),
    ];
    let differences = pairs
        .iter()
        .map(|(got, want)| scaled_error(&flat(*got), &flat(*want)))
        .fold(scaled_error(&forward.qdd, &qdd), f64::max);
    let single = robot.inverse_dynamics_derivatives(
        &q.map(|x| x as f32),
        &qd.map(|x| x as f32),
        &qdd.map(|x| x as f32),
    );
    let widen = |m: [[f32; N]; N]| flat(m.map(|r| r.map(f64::from)));
    let single = scaled_error(&widen(single.dtau_dq), &flat(inverse.dtau_dq)).max(scaled_error(
        &widen(single.dtau_dqd),
        &flat(inverse.dtau_dqd),
    ));
    (differences, single)
}

/// A state of `N` joints from `seed`, away from the Coulomb steps (every |q̇| ≥ 0.2).
fn state<const N: usize>(seed: usize) -> [[f64; N]; 3] {
    let wave = |k: usize, scale: f64| {
        core::array::from_fn(|i| scale * (0.7 * (k * 7 + i * 3 + seed) as f64).sin())
    };
    let qd: [f64; N] = wave(1, 1.5).map(|v: f64| v + 0.2f64.copysign(v));
    [wave(0, 2.5), qd, wave(2, 4.0)]
}

fn check_differences<R: DynamicsDerivatives<N>, const N: usize>(robot: &R, name: &str) {
    let (mut differences, mut single) = (0.0f64, 0.0f64);
    for seed in 0..5 {
        let (d, s) = against_differences(robot, state(seed));
        differences = differences.max(d);
        single = single.max(s);
    }
    println!("{name}: central differences {differences:.1e}, f32 {single:.1e}");
    assert!(differences < 1e-5, "{name}: {differences:e}");
    assert!(single < 1e-4, "{name}: f32 {single:e}");
}

/// The Panda with its two fingers free: a tree of nine joints, whose tangents in lanes (where the
/// build has AVX-512) are kept in the first block of eight directions or in both (a finger's
/// and the arm's in the first, the second finger's across both).
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/trees/panda_free_fingers.urdf",
    base = "panda_link0",
    derivatives = true
)]
struct PandaFreeFingers;

#[test]
fn a_tree_against_central_differences() {
    check_differences(&PandaFreeFingers, "Panda with free fingers");
}

/// Baxter with its fingers free: a tree of 19 joints, two arms with two fingers each and a head,
/// whose ∂τ in lanes (where the build has AVX-512) is fetch-bound and computed by one function
/// per arm with its fingers, each storing its rows: every row must be there.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/trees/baxter_free_fingers.urdf",
    base = "base",
    derivatives = true
)]
struct BaxterFreeFingers;

/// Its ∂q̈ (in lanes, one function per subtree hanging from the base: the head and each arm
/// with its fingers) too: every subtree's rows, `q̈` and pivots must be there.
#[test]
fn a_dual_arm_against_central_differences() {
    let robot = BaxterFreeFingers;
    let mut worst = 0.0f64;
    for seed in 0..5 {
        worst = worst.max(against_differences(&robot, state::<19>(seed)).0);
    }
    println!("Baxter with free fingers: ∂τ and ∂q̈ against central differences {worst:.1e}");
    assert!(worst < 1e-5, "{worst:e}");
}

/// Baxter's ∂τ on one state (in lanes of tangents, each arm's rows in its own layout of
/// directions, where the build has AVX-512) against the same states four at a time in `F64x4`,
/// which computes the columns one by one: to 1e-12 where the routes differ, bit for bit where
/// they do not. On a thread of 64 MB: Baxter's ∂τ on `F64x4` takes more than a thread's 2 MB of
/// stack unoptimized.
#[test]
fn a_dual_arm_in_lanes_against_the_columns() {
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(dual_arm_in_lanes_against_the_columns)
        .expect("a thread")
        .join()
        .expect("the check");
}

fn dual_arm_in_lanes_against_the_columns() {
    let m = Motion::<F64x4, 4, 19>::new(0xba7e5);
    let robot = BaxterFreeFingers;
    let (q, qd, qdd) = (&m.q, &m.qd, &m.qdd);
    let lanes = robot.inverse_dynamics_derivatives(&q.lanes, &qd.lanes, &qdd.lanes);
    let singles: [_; 4] = core::array::from_fn(|l| {
        robot.inverse_dynamics_derivatives(&q.singles[l], &qd.singles[l], &qdd.singles[l])
    });
    // ∂q̈ at the torques of those accelerations: one function per subtree in lanes.
    let tau = robot.inverse_dynamics(&q.lanes, &qd.lanes, &qdd.lanes);
    let forward = robot.forward_dynamics_derivatives(&q.lanes, &qd.lanes, &tau);
    let forward = forward.expect("M ≻ 0");
    let forward_singles: [_; 4] = core::array::from_fn(|l| {
        let tau = robot.inverse_dynamics(&q.singles[l], &qd.singles[l], &qdd.singles[l]);
        let forward = robot.forward_dynamics_derivatives(&q.singles[l], &qd.singles[l], &tau);
        forward.expect("M ≻ 0")
    });
    if routes_differ::<F64x4, 4>() {
        close(
            "Baxter's inverse_dynamics_derivatives",
            lanes,
            &singles,
            1e-12,
        );
        close(
            "Baxter's forward_dynamics_derivatives",
            forward,
            &forward_singles,
            1e-12,
        );
    } else {
        same("Baxter's inverse_dynamics_derivatives", lanes, &singles);
        same(
            "Baxter's forward_dynamics_derivatives",
            forward,
            &forward_singles,
        );
    }
}

#[test]
fn central_differences_and_f32() {
    check_differences(&Puma560, "PUMA 560");
    check_differences(&Stanford, "Stanford");
    check_differences(&NikuPolar, "polar");
    check_differences(&Panda, "Panda");
    let arm = Rubbing {
        fv2: 0.1,
        eps: 0.05,
    };
    check_differences(&arm, "friction arm");
}

#[test]
fn friction_slope_by_hand() {
    let arm = Rubbing {
        fv2: 0.1,
        eps: 0.05,
    };
    let (q, qd, qdd) = ([0.4, -1.1], [0.7, -0.02], [1.5, -0.6]);
    let c = arm.coriolis_matrix(&q, &qd);
    // Joint 1: viscous 0.3, its Coulomb step flat; joint 2: 0.1 + 0.8/ε sech²(q̇2/ε).
    let sech = 1.0 / (qd[1] / 0.05f64).cosh();
    let slope = [0.3, 0.1 + 0.8 / 0.05 * sech * sech];
    let expected: Vec<f64> = (0..4)
        .map(|e| {
            let (i, j) = (e / 2, e % 2);
            2.0 * c[i][j] + if i == j { slope[i] } else { 0.0 }
        })
        .collect();
    let got = arm.inverse_dynamics_derivatives(&q, &qd, &qdd).dtau_dqd;
    let error = scaled_error(&flat(got), &expected);
    assert!(error < 1e-13, "{got:?} vs {expected:?}");
}

/// A two-link arm whose second mass is a field: M is singular where it is 0.
#[derive(Dynamics)]
#[dynamics(
    derivatives = true,
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = 2),
    link(mass = m2),
)]
struct PointMasses {
    m2: f64,
}

#[test]
fn not_positive_definite_is_an_error() {
    let (q, qd, tau) = ([0.3, -0.4], [0.1, 0.2], [1.0, 2.0]);
    let arm = PointMasses { m2: 1.0 };
    assert!(arm.forward_dynamics_derivatives(&q, &qd, &tau).is_ok());
    let limp = PointMasses { m2: 0.0 };
    assert_eq!(
        limp.forward_dynamics_derivatives(&q, &qd, &tau),
        Err(NotPositiveDefinite)
    );
}

/// Random robots, the graph interpreted: `∂τ/∂q` and `∂τ/∂q̇` against central differences of
/// the textbook method's τ.
#[test]
fn random_robots_against_the_textbook_method() {
    let config = Config {
        cases: 48,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(18),
        ..Config::default()
    };
    let result = TestRunner::new(config).run(&case(), |c| {
        let mut eq = dynamics_codegen::derive(&c.robot.model());
        eq.add_derivatives();
        let n = eq.dof;
        let tau = vec![0.0; n];
        let state = State {
            q: &c.q,
            qd: &c.qd,
            qdd: &c.qdd,
            tau: &tau,
        };
        let values = evaluate(&eq, state);
        let derivatives = eq.derivatives.as_ref().expect("traced");
        let reference = c.robot.reference();
        for (block, by_velocity) in derivatives.inverse.iter().zip([false, true]) {
            let generated: Vec<f64> = block
                .iter()
                .flatten()
                .map(|id| values[id.index()])
                .collect();
            let tau = |x: &[f64]| {
                let (q, qd) = if by_velocity {
                    (&c.q[..], x)
                } else {
                    (x, &c.qd[..])
                };
                reference.inverse_dynamics(q, qd, &c.qdd)
            };
            let at = if by_velocity { &c.qd } else { &c.q };
            let mut expected = vec![0.0; n * n];
            for j in 0..n {
                let (mut up, mut down) = (at.clone(), at.clone());
                up[j] += STEP;
                down[j] -= STEP;
                let (a, b) = (tau(&up), tau(&down));
                for i in 0..n {
                    expected[i * n + j] = (a[i] - b[i]) / (2.0 * STEP);
                }
            }
            let error = scaled_error(&generated, &expected);
            proptest::prop_assert!(error < 1e-6, "by q̇: {by_velocity}, error {error:e}");
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}
