//! The joint torque regressor (`DynamicsRegressor`, opt-in with `regressor = true`) against
//! Pinocchio's `computeJointTorqueRegressor` (`data/regressor/`, made by its `make.py`: the
//! regressor in the link frames, the standard parameters from the descriptions, and the torque
//! with the actuator inertia and friction columns): on the D-H reference robots, the Panda and
//! the URDF robots, at 10 samples each, in `f64`, scaled as max|a − b| / max(1, max|b|); `Y π`
//! against `inverse_dynamics`, with parameters and friction from struct fields; on random
//! robots of 1 to 7 joints ([`dynamics_tests::random::case`], the expression graph
//! interpreted), `Y π` plus the joints' columns against the textbook's O(n⁴) method
//! (`dynamics-reference`) minus the springs; `f32` against `f64`.

use dynamics_codegen::model::Value as ModelValue;
use dynamics_codegen::{Family, FamilySet};
use dynamics_reference::scaled_error;
use dynamics_runtime::{Dynamics, DynamicsRegressor};
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::case;
use dynamics_tests::robots::urdf;
use dynamics_tests::robots::{
    NikuPolar, NikuTwoLink, Panda, Puma560, Random1, Random2, Random5, Stanford, Ur5,
};
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestRunner};
use serde_json::Value;

/// Largest accepted scaled error.
const TOLERANCE: f64 = 1e-10;

/// `tests/data/regressor/<name>.json`.
fn data(name: &str) -> Value {
    let path = format!("{}/data/regressor/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The numbers of a JSON array of numbers, or of arrays of them, row after row.
fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(items) => items.iter().flat_map(numbers).collect(),
        Value::Number(x) => vec![x.as_f64().expect("a number")],
        _ => panic!("not a number: {v}"),
    }
}

fn array<const N: usize>(v: &Value) -> [f64; N] {
    numbers(v).try_into().expect("N numbers")
}

/// The regressor as Pinocchio lays it out: row i, then link j's ten columns.
fn rows<const N: usize>(y: &[[[f64; 10]; N]; N]) -> Vec<f64> {
    y.iter().flatten().flatten().copied().collect()
}

/// `Σ_j Σ_k Y[i][j][k] π_jk + Σ_k Y_joint[i][k] π_joint,ik`, per joint.
fn torque<const N: usize>(
    y: &[[[f64; 10]; N]; N],
    pi: &[[f64; 10]; N],
    y_joint: &[[f64; 4]; N],
    pi_joint: &[[f64; 4]; N],
) -> Vec<f64> {
    (0..N)
        .map(|i| {
            let links: f64 = (0..N)
                .map(|j| (0..10).map(|k| y[i][j][k] * pi[j][k]).sum::<f64>())
                .sum();
            links + (0..4).map(|k| y_joint[i][k] * pi_joint[i][k]).sum::<f64>()
        })
        .collect()
}

/// The worst scaled error of the regressor, of the parameters, and of the torque they give
/// against the sample's (Pinocchio's, with the actuator inertia and friction columns).
fn against_pinocchio<R: DynamicsRegressor<N>, const N: usize>(robot: &R, name: &str) -> f64 {
    let file = data(name);
    let pi = robot.standard_parameters::<f64>();
    let pi_joint = robot.joint_parameters::<f64>();
    let flat = |m: &[[f64; 10]; N]| m.iter().flatten().copied().collect::<Vec<f64>>();
    let flat_joint = |m: &[[f64; 4]; N]| m.iter().flatten().copied().collect::<Vec<f64>>();
    let mut worst = scaled_error(&flat(&pi), &numbers(&file["pi"])).max(scaled_error(
        &flat_joint(&pi_joint),
        &numbers(&file["pi_extra"]),
    ));
    let samples = file["samples"].as_array().expect("samples");
    assert_eq!(samples.len(), 10, "{name}");
    for s in samples {
        let [q, qd, qdd] = ["q", "qd", "qdd"].map(|key| array::<N>(&s[key]));
        let y = robot.regressor(&q, &qd, &qdd);
        // Written in place, every element of a buffer that held something else, bit for bit.
        let mut into = [[[f64::NAN; 10]; N]; N];
        robot.regressor_into(&q, &qd, &qdd, &mut into);
        let bits =
            |y: &[[[f64; 10]; N]; N]| rows(y).iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&into), bits(&y), "{name}");
        let y_joint = robot.joint_regressor(&qd, &qdd);
        // Pinocchio's joint columns are n × 4n, joint i's four in block i of row i.
        let block_diagonal: Vec<f64> = (0..N)
            .flat_map(|i| (0..4 * N).map(move |c| (i, c)))
            .map(|(i, c)| if c / 4 == i { y_joint[i][c % 4] } else { 0.0 })
            .collect();
        worst = worst
            .max(scaled_error(&rows(&y), &numbers(&s["Y"])))
            .max(scaled_error(&block_diagonal, &numbers(&s["Y_extra"])))
            .max(scaled_error(
                &torque(&y, &pi, &y_joint, &pi_joint),
                &numbers(&s["tau"]),
            ));
    }
    println!("regressor/{name}: {worst:.1e}");
    assert!(worst < TOLERANCE, "{name}: {worst:e}");
    worst
}

#[test]
fn pinocchio_joint_torque_regressor() {
    against_pinocchio(&Puma560, "puma560");
    against_pinocchio(&Stanford, "stanford");
    against_pinocchio(&Ur5, "ur5");
    against_pinocchio(&NikuTwoLink, "niku_2link");
    against_pinocchio(&NikuPolar, "niku_polar");
    against_pinocchio(&Random1, "random1");
    against_pinocchio(&Random2, "random2");
    against_pinocchio(&Random5, "random5");
    against_pinocchio(&Panda, "panda");
}

/// The URDF robots: π about each URDF link frame's origin, in its axes, as Pinocchio's.
#[test]
fn pinocchio_joint_torque_regressor_of_urdf_robots() {
    against_pinocchio(&urdf::Ur5, "ur5_urdf");
    against_pinocchio(&urdf::Ur10, "ur10_urdf");
    against_pinocchio(&urdf::Panda, "panda_urdf");
    against_pinocchio(&urdf::Z1, "z1_urdf");
    against_pinocchio(&urdf::So101, "so101_urdf");
}

/// A planar two-link arm with actuator inertia, a spring and friction on both joints, joint 2's
/// Coulomb term smoothed with a run-time ε.
#[derive(Dynamics)]
#[dynamics(
    regressor = true,
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = 2, com = [-0.35, 0, 0], inertia = [0, 0.08, 0.08, 0, 0, 0],
         actuator_inertia = 0.05, friction = (viscous = 0.3, coulomb = 1.5, offset = -0.2)),
    link(mass = 1, com = [-0.25, 0, 0], inertia = [0, 0.02, 0.02, 0, 0, 0],
         rotor_inertia = 0.001, gear_ratio = 10, spring = (4, 0.3),
         friction = (viscous = fv2, coulomb = 0.8, smoothing = eps)),
)]
struct Rubbing {
    fv2: f64,
    eps: f64,
}

/// `Y π` plus the joints' columns is `inverse_dynamics` minus the spring torque, for PUMA 560
/// and for an arm with every joint term, in motion and at rest.
#[test]
fn regressor_times_parameters_is_inverse_dynamics() {
    let (q, qd, qdd) = (
        [0.3, -1.2, 0.7, 2.0, -0.4, 1.1],
        [0.5; 6],
        [-1.0, 0.2, 0.9, -0.3, 1.5, 0.1],
    );
    let tau = torque(
        &Puma560.regressor(&q, &qd, &qdd),
        &Puma560.standard_parameters(),
        &Puma560.joint_regressor(&qd, &qdd),
        &Puma560.joint_parameters(),
    );
    let expected = Puma560.inverse_dynamics(&q, &qd, &qdd);
    assert!(
        scaled_error(&tau, &expected) < TOLERANCE,
        "{tau:?} {expected:?}"
    );
    let arm = Rubbing {
        fv2: 0.4,
        eps: 0.05,
    };
    assert_eq!(arm.joint_parameters::<f64>()[1], [0.1, 0.4, 0.8, 0.0]);
    for qd in [[0.8, -0.02], [0.0, 0.0]] {
        let (q, qdd) = ([0.4, -0.9], [0.7, 2.1]);
        let tau = torque(
            &arm.regressor(&q, &qd, &qdd),
            &arm.standard_parameters(),
            &arm.joint_regressor(&qd, &qdd),
            &arm.joint_parameters(),
        );
        let mut expected = arm.inverse_dynamics(&q, &qd, &qdd);
        expected[1] -= 4.0 * (q[1] - 0.3);
        assert!(
            scaled_error(&tau, &expected) < TOLERANCE,
            "{tau:?} {expected:?}"
        );
    }
}

/// A two-link arm whose lengths, masses and gravity are struct fields.
#[derive(Dynamics)]
#[dynamics(
    regressor = true,
    gravity = [0, -g, 0],
    dh = [[q, 0, l1, 0], [q + 0.25, 0, l2, 90 deg]],
    link(mass = m1, com = [-l1 / 2, 0.1, 0], inertia = [0.1, m1 * l1^2 / 12, 0.3, 0.01, 0, 0]),
    link(mass = m2, com = [-l2 / 2, 0, 0.2], inertia = [0.2, 0.1, m2 * l2^2 / 12, 0, 0.02, 0]),
)]
struct TwoLink {
    l1: f64,
    l2: f64,
    m1: f64,
    m2: f32,
    g: f64,
}

/// `Y π` with parameters read from the struct's fields, against `inverse_dynamics`.
#[test]
fn parameters_from_fields() {
    let arm = TwoLink {
        l1: 0.7,
        l2: 0.45,
        m1: 3.2,
        m2: 1.5,
        g: 9.81,
    };
    let (q, qd, qdd) = ([0.4, -0.9], [1.3, -0.6], [0.7, 2.1]);
    let (y, pi) = (
        arm.regressor(&q, &qd, &qdd),
        arm.standard_parameters::<f64>(),
    );
    let tau: Vec<f64> = (0..2)
        .map(|i| {
            (0..2)
                .map(|j| (0..10).map(|k| y[i][j][k] * pi[j][k]).sum::<f64>())
                .sum()
        })
        .collect();
    let expected = arm.inverse_dynamics(&q, &qd, &qdd);
    assert!(
        scaled_error(&tau, &expected) < TOLERANCE,
        "{tau:?} {expected:?}"
    );
    assert_eq!(pi[1][0], 1.5);
}

/// The same code in `f32` and `f64`.
#[test]
fn f32_follows_f64() {
    let (q, qd, qdd) = (
        [0.3, -1.2, 0.7, 2.0, -0.4, 1.1],
        [0.5; 6],
        [-1.0, 0.2, 0.9, -0.3, 1.5, 0.1],
    );
    let wide = rows(&Puma560.regressor::<f64>(&q, &qd, &qdd));
    let narrow = Puma560.regressor::<f32>(
        &q.map(|x| x as f32),
        &qd.map(|x| x as f32),
        &qdd.map(|x| x as f32),
    );
    let narrow: Vec<f64> = narrow
        .iter()
        .flatten()
        .flatten()
        .map(|&x| f64::from(x))
        .collect();
    assert!(scaled_error(&narrow, &wide) < 1e-5);
}

/// A literal of the model as a number.
fn number(v: &ModelValue) -> f64 {
    v.exact().map_or(f64::NAN, |x| x.to_f64())
}

#[test]
fn random_robots_against_the_textbook_method() {
    let config = Config {
        cases: 32,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(27),
        ..Config::default()
    };
    let result = TestRunner::new(config).run(&case(), |c| {
        let robot = c.robot.model();
        let mut eq = dynamics_codegen::derive(&robot);
        eq.add_families(&robot, FamilySet::default().with(Family::Regressor));
        let tau = vec![0.0; eq.dof];
        let state = State {
            q: &c.q,
            qd: &c.qd,
            qdd: &c.qdd,
            tau: &tau,
        };
        let values = evaluate(&eq, state);
        let r = eq.regressor.as_ref().expect("traced");
        let at = |id: &dynamics_codegen::symbolic::NodeId| values[id.index()];
        let n = eq.dof;
        let tau: Vec<f64> = (0..n)
            .map(|i| {
                let links: f64 = (0..n)
                    .map(|j| {
                        (0..10).map(move |k| at(&r.columns[i][j][k]) * at(&r.parameters[j][k]))
                    })
                    .map(Iterator::sum::<f64>)
                    .sum();
                let joint =
                    (0..4).map(|k| at(&r.joint_columns[i][k]) * at(&r.joint_parameters[i][k]));
                links + joint.sum::<f64>()
            })
            .collect();
        let reference = c.robot.reference().inverse_dynamics(&c.q, &c.qd, &c.qdd);
        let expected: Vec<f64> = robot
            .joints
            .iter()
            .enumerate()
            .map(|(i, joint)| {
                let spring = joint.link.spring.as_ref();
                let spring =
                    spring.map_or(0.0, |s| number(&s.stiffness) * (c.q[i] - number(&s.rest)));
                reference[i] - spring
            })
            .collect();
        let error = scaled_error(&tau, &expected);
        proptest::prop_assert!(
            error < 1e-10,
            "error {error:e}: {tau:?} against {expected:?}"
        );
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}
