//! The regressor and the base parameters of robots with mimic joints, checked without them:
//! `Y π` plus the joint terms is the reduced τ at random states; the reduced regressor is `Sᵀ`
//! of the free robot's (every joint a coordinate) at `q_full = S q + o`; the number of base
//! parameters is the numerical rank of the reduced columns stacked over random states, and
//! `Y_B π_B` is τ again.

use crate::unit::algo::tree_tests::{at, robot, R};
use crate::unit::trace::mimic_tests::follow;
use dynamics_codegen::model::{Friction, Robot, Value};
use dynamics_codegen::pipeline::{State, Values};
use dynamics_codegen::trace::base_parameters::JointColumns;
use dynamics_codegen::trace::{derive, Equations};

/// Friction and actuator inertia on every mimic joint, so that its own columns show.
fn with_drives(mut robot: Robot) -> Robot {
    let v = Value::from_f64;
    for joint in robot.joints.iter_mut().filter(|j| j.mimic.is_some()) {
        joint.link.friction = Some(Friction {
            viscous: v(0.4),
            coulomb: v(0.2),
            offset: v(0.05),
            smoothing: Some(v(0.5)),
        });
        joint.link.actuator_inertia = v(0.02);
    }
    robot
}

/// The tree of `mimic_tests` (a revolute joint following its sibling with k = −0.7, o = 0.3,
/// both with θ offsets; a prismatic one following its cousin with k = 1, o = 0), with drives.
fn tree() -> Robot {
    with_drives(crate::unit::trace::mimic_tests::tree())
}

/// A serial arm whose third joint follows the second, `q3 = −0.7 q2 + 0.3`.
fn arm() -> Robot {
    let specs = [
        at(None, R, 0.0, 0.0, 0.0),
        at(None, R, 0.0, 0.0, 1.0),
        at(None, R, 0.0, 0.0, 2.0),
        at(None, R, 0.0, 0.0, 3.0),
    ];
    let mut arm = robot(&specs, false);
    follow(&mut arm, 2, 1, -0.7, 0.3);
    with_drives(arm)
}

/// Deterministic values in (−1, 1).
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        #[allow(clippy::cast_precision_loss)]
        let x = (self.0 >> 11) as f64 / (1_u64 << 53) as f64;
        2.0 * x - 1.0
    }

    fn vector(&mut self, n: usize, scale: f64) -> Vec<f64> {
        (0..n).map(|_| scale * self.next()).collect()
    }
}

/// S (joints × coordinates) and o of `robot`, from its mimic rules.
fn map(robot: &Robot) -> (Vec<Vec<f64>>, Vec<f64>) {
    let coordinates = robot.coordinates();
    let value = |v: &Value| v.eval(&|_| None).expect("a number");
    let mut s = vec![vec![0.0; coordinates.len()]; robot.dof()];
    let mut o = vec![0.0; robot.dof()];
    for (i, joint) in robot.joints.iter().enumerate() {
        let (followed, k) = joint
            .mimic
            .as_ref()
            .map_or((i, 1.0), |m| (m.joint, value(&m.multiplier)));
        o[i] = joint.mimic.as_ref().map_or(0.0, |m| value(&m.offset));
        let c = coordinates
            .iter()
            .position(|&j| j == followed)
            .expect("a coordinate");
        s[i][c] = k;
    }
    (s, o)
}

fn evaluate(eq: &Equations, q: &[f64], qd: &[f64], qdd: &[f64]) -> Values {
    eq.evaluate(&State {
        fields: &[],
        q,
        qd,
        qdd,
        tau: &[],
    })
}

/// Per row of τ, the regressor's columns at a state: every link's ten, then every joint's
/// four in its row (zero in the others).
fn stacked_row(eq: &Equations, at: &Values) -> Vec<Vec<f64>> {
    let r = eq.regressor.as_ref().expect("traced");
    (0..r.columns.len())
        .map(|i| {
            let links = r.columns[i].iter().flat_map(|l| at.vector(l));
            let joints = r.joint_columns.iter().enumerate().flat_map(|(m, c)| {
                let values = at.vector(c);
                values
                    .into_iter()
                    .map(move |x| if r.rows[m] == i { x } else { 0.0 })
            });
            links.chain(joints).collect()
        })
        .collect()
}

/// The standard parameters in [`stacked_row`]'s order.
fn parameters(eq: &Equations, at: &Values) -> Vec<f64> {
    let r = eq.regressor.as_ref().expect("traced");
    let links = r.parameters.iter().flat_map(|p| at.vector(p));
    links
        .chain(r.joint_parameters.iter().flat_map(|p| at.vector(p)))
        .collect()
}

fn close(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= 1e-11 * (1.0 + y.abs()),
            "{what} [{k}]: {x} vs {y}"
        );
    }
}

/// `Y π = τ` on the reduced robot, and `Y = Sᵀ Y_full(S q + o, S q̇, S q̈)` entry by entry.
fn regressor_is_the_projected_one(robot: &Robot) {
    let (s, o) = map(robot);
    let mut free = robot.clone();
    free.joints.iter_mut().for_each(|j| j.mimic = None);
    let (mut eq, mut eq_free) = (derive(robot), derive(&free));
    eq.add_regressor(robot);
    eq_free.add_regressor(&free);
    let n = s[0].len();
    let mut random = Random(41);
    for _ in 0..5 {
        let (q, qd, qdd) = (
            random.vector(n, 3.0),
            random.vector(n, 2.0),
            random.vector(n, 2.0),
        );
        let full = |x: &[f64], o: &[f64]| -> Vec<f64> {
            s.iter()
                .zip(o)
                .map(|(row, o)| row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>() + o)
                .collect()
        };
        let zeros = vec![0.0; s.len()];
        let at = evaluate(&eq, &q, &qd, &qdd);
        let at_free = evaluate(
            &eq_free,
            &full(&q, &o),
            &full(&qd, &zeros),
            &full(&qdd, &zeros),
        );
        let y = stacked_row(&eq, &at);
        let pi = parameters(&eq, &at);
        let y_pi: Vec<f64> = y
            .iter()
            .map(|r| r.iter().zip(&pi).map(|(a, b)| a * b).sum())
            .collect();
        close(&y_pi, &at.vector(&eq.tau), "Y π = τ");
        let y_free = stacked_row(&eq_free, &at_free);
        for (c, row) in y.iter().enumerate() {
            let want: Vec<f64> = (0..row.len())
                .map(|p| (0..s.len()).map(|i| s[i][c] * y_free[i][p]).sum())
                .collect();
            close(row, &want, "Y = Sᵀ Y_full");
        }
    }
}

#[test]
fn the_regressor_of_a_tree_with_mimics_is_its_free_regressor_projected() {
    regressor_is_the_projected_one(&tree());
}

#[test]
fn the_regressor_of_an_arm_whose_third_joint_follows_the_second() {
    regressor_is_the_projected_one(&arm());
}

/// Numerical rank of `rows` (each a row), by Gaussian elimination with full pivoting on the
/// columns scaled to unit norm.
fn rank(mut rows: Vec<Vec<f64>>) -> usize {
    let width = rows[0].len();
    for c in 0..width {
        let norm = rows.iter().map(|r| r[c] * r[c]).sum::<f64>().sqrt();
        if norm > 0.0 {
            rows.iter_mut().for_each(|r| r[c] /= norm);
        }
    }
    let mut rank = 0;
    loop {
        let mut best = (0.0, 0, 0);
        for (i, r) in rows.iter().enumerate().skip(rank) {
            for (c, x) in r.iter().enumerate() {
                if x.abs() > best.0 {
                    best = (x.abs(), i, c);
                }
            }
        }
        if best.0 <= 1e-8 {
            return rank;
        }
        rows.swap(rank, best.1);
        let pivot = rows[rank].clone();
        for r in rows.iter_mut().skip(rank + 1) {
            let f = r[best.2] / pivot[best.2];
            r.iter_mut().zip(&pivot).for_each(|(x, p)| *x -= f * p);
        }
        rank += 1;
    }
}

/// The base parameters of `robot` (its described joint terms): as many as the rank of the
/// reduced columns over random states, and `Y_B π_B = τ`.
fn base_parameters_have_the_rank(robot: &Robot) -> usize {
    let mut eq = derive(robot);
    let joints: Vec<JointColumns> = robot.joints.iter().map(JointColumns::described).collect();
    let base = eq.base_parameters(robot, &joints).expect("numbers");
    let n = eq.dof;
    let taken = |m: usize| -> [bool; 4] {
        let j = joints[m];
        [j.actuator_inertia, j.viscous, j.coulomb, j.offset]
    };
    let mut random = Random(7);
    let mut stacked = Vec::new();
    for _ in 0..12 {
        let (q, qd, qdd) = (
            random.vector(n, 3.0),
            random.vector(n, 2.0),
            random.vector(n, 2.0),
        );
        let at = evaluate(&eq, &q, &qd, &qdd);
        let links = robot.dof() * 10;
        for row in stacked_row(&eq, &at) {
            // The joint terms the description gives only, as the base parameters take them.
            let kept = row
                .iter()
                .enumerate()
                .filter(|&(p, _)| p < links || taken((p - links) / 4)[(p - links) % 4]);
            stacked.push(kept.map(|(_, &x)| x).collect());
        }
        let y_b = at.matrix(&base.regressor);
        let pi_b = at.vector(&base.values);
        let tau: Vec<f64> = y_b
            .iter()
            .map(|r| r.iter().zip(&pi_b).map(|(a, b)| a * b).sum())
            .collect();
        close(&tau, &at.vector(&eq.tau), "Y_B π_B = τ");
    }
    assert_eq!(
        base.parameters.len(),
        rank(stacked),
        "base parameters against the rank"
    );
    base.parameters.len()
}

#[test]
fn the_base_parameters_of_robots_with_mimics_are_the_reduced_rank() {
    base_parameters_have_the_rank(&tree());
    base_parameters_have_the_rank(&arm());
}

#[test]
fn the_panda_with_its_mimic_finger() {
    let panda = crate::unit::trace::mimic_tests::panda().robot;
    regressor_is_the_projected_one(&panda);
    let b = base_parameters_have_the_rank(&panda);
    // The free Panda's fingers move apart: the coupled one identifies fewer combinations.
    let mut free = panda.clone();
    free.joints.iter_mut().for_each(|j| j.mimic = None);
    assert!(b < base_parameters_have_the_rank(&free), "{b}");
}

/// The simplified models of a mimic robot, once refused, are built beside its regressor (their
/// bounds are checked in `simplify/mimic_tests.rs`).
#[test]
fn the_simplified_models_of_a_mimic_robot_are_built_beside_its_regressor() {
    use dynamics_codegen::method::{Family, FamilySet};
    use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
    let arm = arm();
    let joint = JointEnvelope {
        lower: -1.0,
        upper: 1.0,
        speed: 1.0,
        acceleration: 1.0,
    };
    let request = Simplification {
        tolerance: vec![0.01; 3],
        envelope: Envelope {
            joints: vec![joint; 3],
        },
    };
    let families = FamilySet::default().with(Family::Regressor);
    let (eq, simplified) = dynamics_codegen::pipeline::equations(&arm, families, Some(&request));
    simplified.expect("asked").expect("built");
    assert!(eq.families.contains(Family::Simplified) && eq.families.contains(Family::Regressor));
}
