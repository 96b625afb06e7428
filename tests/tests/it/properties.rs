//! Property tests of the generator's closed forms on random robots.
//!
//! Every case ([`dynamics_tests::random::case`]) is a random serial robot (1 to 6 joints,
//! revolute or prismatic, standard or modified D-H, random D-H values with exact 0°/±90°/180°
//! angles and exact zero lengths mixed in, random gravity, physically consistent inertial data,
//! optional actuator inertia and joint springs) and a random state `q`, `q̇`, `q̈`. The system under test is the closed form of
//! [`dynamics_codegen::derive`], evaluated by interpreting its expression graph; the oracle is
//! `dynamics-reference`, the textbook's O(n⁴) trace method, built from the same numbers.
//!
//! Properties, one test each:
//!
//! 1. [`generated_matches_reference`]: τ, M, the Christoffel symbols D_ijk, C, C q̇, g,
//!    C q̇ + g and both energies equal the reference's.
//! 2. [`mass_matrix_is_symmetric_positive_definite`]: M = Mᵀ and M ≻ 0.
//! 3. [`mass_matrix_derivative_minus_twice_coriolis_is_skew`]: xᵀ(Ṁ − 2C)x = 0, with Ṁ by
//!    central differences of the generated M along q̇.
//! 4. [`power_balance`]: q̇ᵀ(τ − g) = dK/dt along a motion through (q, q̇, q̈).
//! 5. [`gravity_is_potential_gradient`]: g = ∂P/∂q.
//! 6. [`algorithms_agree`]: the generator's algorithms agree with each other: column j of M
//!    is τ(q, 0, e_j) − τ(q, 0, 0), g = τ(q, 0, 0), C q̇ = (C q̇ + g) − g, C(q, q̇) q̇ equals
//!    the Newton-Euler C q̇, and τ = M q̈ + C q̇ + g.
//!
//! The runs are deterministic (fixed seed and case count) and write no failure-persistence
//! files. A failure reports the shrunk robot and state.

use dynamics_reference::scaled_error;
use std::cell::RefCell;

use dynamics_codegen::symbolic::NodeId;
use dynamics_codegen::Equations;
use dynamics_reference::nalgebra::{DMatrix, DVector};
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::{case, Case, RobotSpec};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestError, TestRunner};

/// Cases per property.
const CASES: u32 = 64;
/// Relative tolerance between the closed form and the reference.
const EXACT: f64 = 1e-9;
/// Relative tolerance of identities checked by central differences.
const FINITE_DIFFERENCE: f64 = 1e-6;
/// Step of the central differences.
const STEP: f64 = 1e-5;

/// Runs `test` on [`CASES`] random cases with a fixed seed; panics with the shrunk case on
/// failure.
fn check(seed: u64, test: impl Fn(&Case) -> Result<(), TestCaseError>) {
    let config = Config {
        cases: CASES,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(seed),
        ..Config::default()
    };
    match TestRunner::new(config).run(&case(), |c| test(&c)) {
        Ok(()) => {}
        Err(TestError::Fail(reason, case)) => panic!("{reason}\nminimal failing case: {case:#?}"),
        Err(TestError::Abort(reason)) => panic!("aborted: {reason}"),
    }
}

// ---------------------------------------------------------------------------------------------
// The closed form, interpreted

/// The generator's equations of a robot, evaluated by interpreting the expression graph the
/// way the emitted code does.
struct Generated {
    eq: Equations,
}

/// The values of every node of the graph at one state.
struct Values(Vec<f64>);

impl Generated {
    fn new(robot: &RobotSpec) -> Generated {
        Generated {
            eq: dynamics_codegen::derive(&robot.model()),
        }
    }

    fn at(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> Values {
        let tau = self.zeros();
        let state = State {
            q,
            qd,
            qdd,
            tau: &tau,
        };
        Values(evaluate(&self.eq, state))
    }

    fn zeros(&self) -> Vec<f64> {
        vec![0.0; self.eq.dof]
    }

    fn mass_matrix(&self, q: &[f64]) -> DMatrix<f64> {
        let z = self.zeros();
        self.at(q, &z, &z).matrix(&self.eq.mass)
    }

    fn inverse_dynamics(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> DVector<f64> {
        self.at(q, qd, qdd).vector(&self.eq.tau)
    }

    fn gravity_torques(&self, q: &[f64]) -> DVector<f64> {
        let z = self.zeros();
        self.at(q, &z, &z).vector(&self.eq.gravity)
    }

    fn kinetic_energy(&self, q: &[f64], qd: &[f64]) -> f64 {
        let z = self.zeros();
        self.at(q, qd, &z).scalar(self.eq.kinetic_energy)
    }

    fn potential_energy(&self, q: &[f64]) -> f64 {
        let z = self.zeros();
        self.at(q, &z, &z).scalar(self.eq.potential_energy)
    }
}

impl Values {
    fn scalar(&self, id: NodeId) -> f64 {
        self.0[id.index()]
    }

    fn vector(&self, ids: &[NodeId]) -> DVector<f64> {
        DVector::from_iterator(ids.len(), ids.iter().map(|id| self.scalar(*id)))
    }

    fn matrix(&self, ids: &[Vec<NodeId>]) -> DMatrix<f64> {
        DMatrix::from_fn(ids.len(), ids.len(), |i, j| self.scalar(ids[i][j]))
    }
}

// ---------------------------------------------------------------------------------------------
// Helpers

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// `q + t v`.
fn along(q: &[f64], t: f64, v: &[f64]) -> Vec<f64> {
    q.iter().zip(v).map(|(a, b)| a + t * b).collect()
}

// ---------------------------------------------------------------------------------------------
// Properties

/// Property 1: the closed form equals the reference, to `EXACT` relative to
/// `max(1, max |reference|)`, for τ, M, D_ijk, C, C q̇, g, C q̇ + g, K and P.
#[test]
fn generated_matches_reference() {
    const NAMES: [&str; 9] = ["tau", "M", "D_ijk", "C", "C qd", "g", "C qd + g", "K", "P"];
    let worst = RefCell::new([0.0f64; 9]);
    check(1, |c| {
        let generated = Generated::new(&c.robot);
        let reference = c.robot.reference();
        let eq = &generated.eq;
        let n = eq.dof;
        let (q, qd, qdd) = (&c.q, &c.qd, &c.qdd);
        let v = generated.at(q, qd, qdd);
        let christoffel: Vec<f64> = eq
            .christoffel
            .iter()
            .flatten()
            .flatten()
            .map(|id| v.scalar(*id))
            .collect();
        let reference_christoffel = reference.christoffel(q);
        let want_christoffel: Vec<f64> = (0..n)
            .flat_map(|i| (0..n).flat_map(move |j| (0..n).map(move |k| (i, j, k))))
            .map(|(i, j, k)| reference_christoffel[i][(j, k)])
            .collect();
        let row_major = |m: DMatrix<f64>| m.transpose().as_slice().to_vec();
        let bias = reference.coriolis_torques(q, qd) + reference.gravity_torques(q);
        let checks: [(Vec<f64>, Vec<f64>); 9] = [
            (
                v.vector(&eq.tau).as_slice().to_vec(),
                reference.inverse_dynamics(q, qd, qdd).as_slice().to_vec(),
            ),
            (
                row_major(v.matrix(&eq.mass)),
                row_major(reference.mass_matrix(q)),
            ),
            (christoffel, want_christoffel),
            (
                row_major(v.matrix(&eq.coriolis)),
                row_major(reference.coriolis_matrix(q, qd)),
            ),
            (
                v.vector(&eq.coriolis_torques).as_slice().to_vec(),
                reference.coriolis_torques(q, qd).as_slice().to_vec(),
            ),
            (
                v.vector(&eq.gravity).as_slice().to_vec(),
                reference.gravity_torques(q).as_slice().to_vec(),
            ),
            (
                v.vector(&eq.bias).as_slice().to_vec(),
                bias.as_slice().to_vec(),
            ),
            (
                vec![v.scalar(eq.kinetic_energy)],
                vec![reference.kinetic_energy(q, qd)],
            ),
            (
                vec![v.scalar(eq.potential_energy)],
                vec![reference.potential_energy(q)],
            ),
        ];
        for (k, (got, want)) in checks.iter().enumerate() {
            let e = scaled_error(got, want);
            prop_assert!(
                e < EXACT,
                "{} off by {e:e}\n got {got:?}\nwant {want:?}",
                NAMES[k]
            );
            let mut worst = worst.borrow_mut();
            worst[k] = worst[k].max(e);
        }
        Ok(())
    });
    let worst = worst.into_inner();
    for (name, e) in NAMES.iter().zip(worst) {
        eprintln!("worst scaled error of {name}: {e:.1e}");
    }
}

/// Property 2: M is symmetric and positive definite (its Cholesky factorisation exists and
/// its smallest eigenvalue is positive).
#[test]
fn mass_matrix_is_symmetric_positive_definite() {
    check(2, |c| {
        let generated = Generated::new(&c.robot);
        let m = generated.mass_matrix(&c.q);
        let scale = max_abs(m.as_slice()).max(1.0);
        let asymmetry = max_abs((&m - m.transpose()).as_slice()) / scale;
        prop_assert!(asymmetry < EXACT, "M is not symmetric ({asymmetry:e}): {m}");
        prop_assert!(
            m.clone().cholesky().is_some(),
            "M has no Cholesky factor: {m}"
        );
        let smallest = m.clone().symmetric_eigenvalues().min();
        prop_assert!(smallest > 0.0, "M has eigenvalue {smallest:e}: {m}");
        Ok(())
    });
}

/// Property 3: Ṁ − 2C is skew-symmetric: xᵀ(Ṁ − 2C)x = 0 for a random x, and
/// (Ṁ − 2C) + (Ṁ − 2C)ᵀ = 0 entry by entry (that is, Ṁ = C + Cᵀ). Ṁ is the central
/// difference of the generated M along q̇.
#[test]
fn mass_matrix_derivative_minus_twice_coriolis_is_skew() {
    check(3, |c| {
        let generated = Generated::new(&c.robot);
        let (q, qd) = (&c.q, &c.qd);
        let m_dot = (generated.mass_matrix(&along(q, STEP, qd))
            - generated.mass_matrix(&along(q, -STEP, qd)))
            / (2.0 * STEP);
        let coriolis = generated
            .at(q, qd, &generated.zeros())
            .matrix(&generated.eq.coriolis);
        let skew = &m_dot - 2.0 * &coriolis;
        let scale = max_abs(m_dot.as_slice())
            .max(2.0 * max_abs(coriolis.as_slice()))
            .max(1.0);
        let symmetric_part = max_abs((&skew + skew.transpose()).as_slice()) / scale;
        prop_assert!(
            symmetric_part < FINITE_DIFFERENCE,
            "Ṁ − 2C has a symmetric part of {symmetric_part:e}\nṀ = {m_dot}\nC = {coriolis}"
        );
        let x = DVector::from_column_slice(&c.x);
        let quadratic = (x.transpose() * &skew * &x)[(0, 0)];
        let scale = scale * x.norm_squared().max(1.0);
        prop_assert!(
            quadratic.abs() / scale < FINITE_DIFFERENCE,
            "xᵀ(Ṁ − 2C)x = {quadratic:e}"
        );
        Ok(())
    });
}

/// Property 4: power balance, q̇ᵀ(τ − g) = dK/dt, with dK/dt the central difference of the
/// generated kinetic energy along (q + t q̇, q̇ + t q̈) at t = 0.
#[test]
fn power_balance() {
    check(4, |c| {
        let generated = Generated::new(&c.robot);
        let (q, qd, qdd) = (&c.q, &c.qd, &c.qdd);
        let tau = generated.inverse_dynamics(q, qd, qdd);
        let g = generated.gravity_torques(q);
        let power = DVector::from_column_slice(qd).dot(&(&tau - &g));
        let kinetic = |t: f64| generated.kinetic_energy(&along(q, t, qd), &along(qd, t, qdd));
        let k_dot = (kinetic(STEP) - kinetic(-STEP)) / (2.0 * STEP);
        let scale = qd
            .iter()
            .zip(tau.iter().zip(g.iter()))
            .map(|(v, (t, g))| (v * t).abs() + (v * g).abs())
            .sum::<f64>()
            .max(kinetic(0.0))
            .max(1.0);
        prop_assert!(
            (power - k_dot).abs() / scale < FINITE_DIFFERENCE,
            "q̇ᵀ(τ − g) = {power}, dK/dt = {k_dot}"
        );
        Ok(())
    });
}

/// Property 5: g = ∂P/∂q, each partial derivative by central differences of the generated
/// potential energy.
#[test]
fn gravity_is_potential_gradient() {
    check(5, |c| {
        let generated = Generated::new(&c.robot);
        let q = &c.q;
        let n = q.len();
        let g = generated.gravity_torques(q);
        let gradient: Vec<f64> = (0..n)
            .map(|i| {
                let mut e = vec![0.0; n];
                e[i] = 1.0;
                (generated.potential_energy(&along(q, STEP, &e))
                    - generated.potential_energy(&along(q, -STEP, &e)))
                    / (2.0 * STEP)
            })
            .collect();
        let scale = max_abs(g.as_slice())
            .max(generated.potential_energy(q).abs())
            .max(1.0);
        let e = max_abs((g.clone() - DVector::from_vec(gradient.clone())).as_slice()) / scale;
        prop_assert!(
            e < FINITE_DIFFERENCE,
            "g and ∂P/∂q differ by {e:e}\n    g = {:?}\n∂P/∂q = {gradient:?}",
            g.as_slice()
        );
        Ok(())
    });
}

/// Property 6: the generator's outputs agree with each other: column j of M is
/// τ(q, 0, e_j) − τ(q, 0, 0); g = τ(q, 0, 0); C q̇ = (C q̇ + g) − g; the Christoffel C(q, q̇)
/// times q̇ is the Newton-Euler C q̇; and τ = M q̈ + C q̇ + g.
#[test]
fn algorithms_agree() {
    check(6, |c| {
        let generated = Generated::new(&c.robot);
        let eq = &generated.eq;
        let n = eq.dof;
        let (q, qd, qdd) = (&c.q, &c.qd, &c.qdd);
        let z = generated.zeros();
        let m = generated.mass_matrix(q);
        let tau0 = generated.inverse_dynamics(q, &z, &z);
        let columns = DMatrix::from_columns(
            &(0..n)
                .map(|j| {
                    let mut e = vec![0.0; n];
                    e[j] = 1.0;
                    generated.inverse_dynamics(q, &z, &e) - &tau0
                })
                .collect::<Vec<_>>(),
        );
        let v = generated.at(q, qd, qdd);
        let (tau, g, bias, cqd, coriolis) = (
            v.vector(&eq.tau),
            v.vector(&eq.gravity),
            v.vector(&eq.bias),
            v.vector(&eq.coriolis_torques),
            v.matrix(&eq.coriolis),
        );
        let qd_v = DVector::from_column_slice(qd);
        let qdd_v = DVector::from_column_slice(qdd);
        let checks: [(&str, DVector<f64>, DVector<f64>); 5] = [
            (
                "M (columns of τ(q, 0, e_j) − τ(q, 0, 0))",
                DVector::from_column_slice(columns.as_slice()),
                DVector::from_column_slice(m.as_slice()),
            ),
            ("g (τ(q, 0, 0))", tau0, g.clone()),
            ("C qd ((C qd + g) − g)", &bias - &g, cqd.clone()),
            ("C qd (C(q, qd) qd)", &coriolis * &qd_v, cqd.clone()),
            ("τ (M qdd + C qd + g)", &m * &qdd_v + &cqd + &g, tau),
        ];
        for (what, got, want) in checks {
            let e = scaled_error(got.as_slice(), want.as_slice());
            prop_assert!(
                e < EXACT,
                "{what} off by {e:e}\n got {:?}\nwant {:?}",
                got.as_slice(),
                want.as_slice()
            );
        }
        Ok(())
    });
}
