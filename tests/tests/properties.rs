//! Property tests of the generator's closed forms on random robots.
//!
//! Every case is a random serial robot (1 to 6 joints, revolute or prismatic, standard or
//! modified D-H, random D-H values with exact 0°/±90°/180° angles and exact zero lengths mixed
//! in, random gravity, physically consistent inertial data, optional actuator inertia and joint
//! springs) and a random state `q`, `q̇`, `q̈`. The system under test is the closed form of
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
use std::f64::consts::{FRAC_PI_2, PI};

use dynamics_codegen::model::{self, Convention, JointKind, Spring, Value};
use dynamics_codegen::symbolic::{NodeId, Number, Var};
use dynamics_codegen::Equations;
use dynamics_reference::nalgebra::{DMatrix, DVector};
use proptest::collection::vec;
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

// ---------------------------------------------------------------------------------------------
// Random robots

/// A D-H angle: a float, or an exact multiple of π written in one of the two ways the
/// generator recognises.
#[derive(Clone, Copy, Debug)]
enum Angle {
    /// Radians.
    Float(f64),
    /// `k · π/2`, stored as the nearest float (as description files store `90 deg`).
    QuarterTurnsFloat(i8),
    /// `num/den · π`, written symbolically: exact sine and cosine for quarter turns, an exact
    /// multiple of π without rational sine and cosine otherwise (30°, 45°, …).
    PiFraction(i8, i8),
}

impl Angle {
    fn radians(self) -> f64 {
        match self {
            Angle::Float(x) => x,
            Angle::QuarterTurnsFloat(k) => f64::from(k) * FRAC_PI_2,
            Angle::PiFraction(num, den) => f64::from(num) * PI / f64::from(den),
        }
    }

    fn value(self) -> Value {
        match self {
            Angle::Float(x) => Value::from_f64(x),
            Angle::QuarterTurnsFloat(k) => Value::from_f64(f64::from(k) * FRAC_PI_2),
            Angle::PiFraction(num, den) => Value::Mul(
                Box::new(Value::Num(
                    Number::ratio(i128::from(num), i128::from(den)).expect("nonzero denominator"),
                )),
                Box::new(Value::Pi),
            ),
        }
    }
}

/// One joint and its link, in plain numbers.
#[derive(Clone, Debug)]
struct JointSpec {
    kind: JointKind,
    theta: Angle,
    d: f64,
    a: f64,
    alpha: Angle,
    mass: f64,
    com: [f64; 3],
    /// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` about the centre of mass.
    inertia: [f64; 6],
    actuator_inertia: f64,
    /// `(stiffness, rest)`.
    spring: Option<(f64, f64)>,
}

/// A robot in plain numbers, turned into both the generator's and the reference's model.
#[derive(Clone, Debug)]
struct RobotSpec {
    convention: Convention,
    gravity: [f64; 3],
    joints: Vec<JointSpec>,
}

impl RobotSpec {
    fn model(&self) -> model::Robot {
        let v = Value::from_f64;
        model::Robot {
            name: "random".into(),
            convention: self.convention,
            gravity: self.gravity.map(v),
            joints: self
                .joints
                .iter()
                .map(|j| model::Joint {
                    kind: j.kind,
                    theta: j.theta.value(),
                    d: v(j.d),
                    a: v(j.a),
                    alpha: j.alpha.value(),
                    mass: v(j.mass),
                    com: j.com.map(v),
                    inertia: j.inertia.map(v),
                    actuator_inertia: v(j.actuator_inertia),
                    spring: j.spring.map(|(k, rest)| Spring {
                        stiffness: v(k),
                        rest: v(rest),
                    }),
                })
                .collect(),
        }
    }

    fn reference(&self) -> dynamics_reference::Robot {
        use dynamics_reference as r;
        r::Robot {
            name: "random".into(),
            description: String::new(),
            convention: match self.convention {
                Convention::Standard => r::Convention::Standard,
                Convention::Modified => r::Convention::Modified,
            },
            gravity: self.gravity,
            joints: self
                .joints
                .iter()
                .map(|j| r::Joint {
                    kind: match j.kind {
                        JointKind::Revolute => r::JointKind::Revolute,
                        JointKind::Prismatic => r::JointKind::Prismatic,
                    },
                    theta: j.theta.radians(),
                    d: j.d,
                    a: j.a,
                    alpha: j.alpha.radians(),
                    mass: j.mass,
                    com: j.com,
                    inertia: j.inertia,
                    actuator_inertia: j.actuator_inertia,
                    spring_stiffness: j.spring.map_or(0.0, |(k, _)| k),
                    spring_rest: j.spring.map_or(0.0, |(_, rest)| rest),
                })
                .collect(),
        }
    }
}

/// A robot and a state.
#[derive(Clone, Debug)]
struct Case {
    robot: RobotSpec,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    /// A random direction in joint space.
    x: Vec<f64>,
}

/// An angle: mostly a float in [−π, π), sometimes exactly 0, ±90° or 180° (as a float or
/// symbolically), sometimes a symbolic multiple of π that is not a quarter turn.
fn angle() -> impl Strategy<Value = Angle> {
    let quarter_turns = prop_oneof![Just(0i8), Just(1), Just(-1), Just(2)];
    let other_fractions = prop_oneof![Just((1i8, 3i8)), Just((1, 4)), Just((-1, 6)), Just((3, 4))];
    prop_oneof![
        8 => (-PI..PI).prop_map(Angle::Float),
        2 => quarter_turns.clone().prop_map(Angle::QuarterTurnsFloat),
        2 => quarter_turns.prop_map(|k| Angle::PiFraction(k, 2)),
        1 => other_fractions.prop_map(|(num, den)| Angle::PiFraction(num, den)),
    ]
}

/// A length in [−1, 1], sometimes exactly zero.
fn length() -> impl Strategy<Value = f64> {
    prop_oneof![3 => -1.0..1.0, 1 => Just(0.0)]
}

/// `R diag(p) Rᵀ` as `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`, with `R` the rotation of the
/// quaternion `w, x, y, z` (normalised; the identity if it is too short).
fn rotated_inertia(p: [f64; 3], [w, x, y, z]: [f64; 4]) -> [f64; 6] {
    let norm = (w * w + x * x + y * y + z * z).sqrt();
    let (w, x, y, z) = if norm < 0.1 {
        (1.0, 0.0, 0.0, 0.0)
    } else {
        (w / norm, x / norm, y / norm, z / norm)
    };
    let r = [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ];
    let entry = |i: usize, j: usize| (0..3).map(|k| r[i][k] * p[k] * r[j][k]).sum::<f64>();
    [
        entry(0, 0),
        entry(1, 1),
        entry(2, 2),
        entry(0, 1),
        entry(0, 2),
        entry(1, 2),
    ]
}

/// A physically consistent inertia tensor about the centre of mass: principal moments
/// `p = (b + c, a + c, a + b)` from positive second moments `a, b, c` (so the triangle
/// inequality holds), in principal axes rotated by a random rotation, or not rotated.
fn inertia() -> impl Strategy<Value = [f64; 6]> {
    let second_moments = proptest::array::uniform3(0.001..0.2f64);
    let rotation = prop_oneof![
        1 => Just([1.0, 0.0, 0.0, 0.0]),
        3 => proptest::array::uniform4(-1.0..1.0f64),
    ];
    (second_moments, rotation)
        .prop_map(|([a, b, c], quaternion)| rotated_inertia([b + c, a + c, a + b], quaternion))
}

fn joint() -> impl Strategy<Value = JointSpec> {
    let kind = prop_oneof![
        2 => Just(JointKind::Revolute),
        1 => Just(JointKind::Prismatic),
    ];
    let com = proptest::array::uniform3(prop_oneof![3 => -0.5..0.5, 1 => Just(0.0)]);
    let actuator = prop_oneof![Just(0.0), 0.0..0.5];
    let spring = prop_oneof![Just(None), (0.0..20.0, -1.0..1.0).prop_map(Some)];
    (
        kind,
        angle(),
        length(),
        length(),
        angle(),
        0.1..5.0,
        com,
        inertia(),
        actuator,
        spring,
    )
        .prop_map(
            |(kind, theta, d, a, alpha, mass, com, inertia, actuator_inertia, spring)| JointSpec {
                kind,
                theta,
                d,
                a,
                alpha,
                mass,
                com,
                inertia,
                actuator_inertia,
                spring,
            },
        )
}

fn robot() -> impl Strategy<Value = RobotSpec> {
    let convention = prop_oneof![Just(Convention::Standard), Just(Convention::Modified)];
    let gravity = prop_oneof![
        1 => Just([0.0, 0.0, -9.81]),
        1 => Just([0.0, -9.81, 0.0]),
        2 => proptest::array::uniform3(-10.0..10.0),
    ];
    (convention, gravity, vec(joint(), 1..=6)).prop_map(|(convention, gravity, joints)| RobotSpec {
        convention,
        gravity,
        joints,
    })
}

fn case() -> impl Strategy<Value = Case> {
    robot().prop_flat_map(|robot| {
        let n = robot.joints.len();
        (
            Just(robot),
            vec(-PI..PI, n),
            vec(-2.0..2.0, n),
            vec(-2.0..2.0, n),
            vec(-1.0..1.0, n),
        )
            .prop_map(|(robot, q, qd, qdd, x)| Case {
                robot,
                q,
                qd,
                qdd,
                x,
            })
    })
}

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
    /// Angle offset of each joint's `sin`/`cos` inputs (0 where it was folded).
    offsets: Vec<f64>,
}

/// The values of every node of the graph at one state.
struct Values(Vec<f64>);

impl Generated {
    fn new(robot: &RobotSpec) -> Generated {
        let eq = dynamics_codegen::derive(&robot.model());
        // The offsets are constant nodes: their values do not depend on the inputs.
        let constants = eq.graph.eval(|_| 0.0);
        let offsets = eq
            .angle_offsets
            .iter()
            .map(|o| o.map_or(0.0, |id| constants[id.index()]))
            .collect();
        Generated { eq, offsets }
    }

    fn at(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> Values {
        Values(self.eq.graph.eval(|v| match v {
            Var::Q(i) => q[usize::from(i)],
            Var::SinQ(i) => (q[usize::from(i)] + self.offsets[usize::from(i)]).sin(),
            Var::CosQ(i) => (q[usize::from(i)] + self.offsets[usize::from(i)]).cos(),
            Var::Qd(i) => qd[usize::from(i)],
            Var::Qdd(i) => qdd[usize::from(i)],
            Var::Param(k) => panic!("the robot has no struct fields, yet parameter {k} appears"),
        }))
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
