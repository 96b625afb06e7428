//! The regressor and the base parameters of the Panda with its URDF's mimic finger (9 links, 8
//! coordinates), traced through the front door, against Pinocchio 4.1
//! (`tests/data/trees/panda_fingers_regressor.json`, by `mimic_regressor.py`:
//! `computeJointTorqueRegressor` of the free model at `q_full = G q + o`, projected by `Gᵀ`):
//! the regressor's 8 rows of 90 columns (10 per link, the mimic finger's own kept), the standard
//! parameters, `Y π = τ`; the number of base parameters against the numerical rank of
//! Pinocchio's projected regressor stacked over the samples, and `Y_B π_B = τ`.

use dynamics_codegen::pipeline::{load, Source, State, Values};
use dynamics_codegen::{derive, Chain, Equations, JointColumns};
use dynamics_reference::scaled_error;
use dynamics_tests::reference::TOLERANCE;
use serde_json::Value;

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        x => vec![x.as_f64().expect("a number")],
    }
}

fn data() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/trees/panda_fingers_regressor.json"
    );
    let text = std::fs::read_to_string(path).expect("readable");
    serde_json::from_str(&text).expect("JSON")
}

/// The Panda of `robots/urdf/panda.urdf`, its equations and its regressor.
fn panda() -> (dynamics_codegen::model::Robot, Equations) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf/panda.urdf");
    let text = std::fs::read_to_string(path).expect("readable");
    let source = Source {
        path: "panda.urdf",
        text: Some(&text),
        chain: Chain {
            base: Some("panda_link0"),
            ..Default::default()
        },
        ..Source::default()
    };
    let robot = load(&source).expect("loads").robot;
    let mut eq = derive(&robot);
    eq.add_regressor(&robot);
    (robot, eq)
}

fn at(eq: &Equations, sample: &Value) -> Values {
    let [q, qd, qdd] = ["q", "qd", "qdd"].map(|k| numbers(&sample[k]));
    eq.evaluate(&State {
        fields: &[],
        q: &q,
        qd: &qd,
        qdd: &qdd,
        tau: &[],
    })
}

fn dot(row: &[f64], x: &[f64]) -> f64 {
    row.iter().zip(x).map(|(a, b)| a * b).sum()
}

#[test]
fn the_mimic_pandas_regressor_is_pinocchios_projected() {
    let (_, eq) = panda();
    let r = eq.regressor.as_ref().expect("traced");
    assert_eq!((r.columns.len(), r.parameters.len()), (8, 9));
    let file = data();
    let samples = file["samples"].as_array().expect("samples");
    let first = at(&eq, &samples[0]);
    let pi: Vec<f64> = r.parameters.iter().flat_map(|p| first.vector(p)).collect();
    let mut worst = scaled_error(&pi, &numbers(&file["pi"]));
    for sample in samples {
        let values = at(&eq, sample);
        let rows: Vec<Vec<f64>> = (r.columns.iter())
            .map(|row| row.iter().flat_map(|link| values.vector(link)).collect())
            .collect();
        let tau: Vec<f64> = rows.iter().map(|row| dot(row, &pi)).collect();
        worst = worst
            .max(scaled_error(&rows.concat(), &numbers(&sample["Y"])))
            .max(scaled_error(&tau, &numbers(&sample["tau"])));
    }
    println!("mimic Panda's regressor against Pinocchio: {worst:.1e}");
    assert!(worst < TOLERANCE, "{worst:e}");
}

/// Numerical rank of `rows`, its columns scaled to unit norm: the singular values above 1e-9 of
/// the largest. Columns of rounding alone (below 1e-12 of the largest column) are dropped
/// first: Pinocchio's has one of norm 8e-16, which scaling would make a unit column.
pub(crate) fn rank(rows: &[Vec<f64>]) -> usize {
    let width = rows[0].len();
    let norms: Vec<f64> = (0..width)
        .map(|c| rows.iter().map(|r| r[c] * r[c]).sum::<f64>().sqrt())
        .collect();
    let largest = norms.iter().fold(0.0_f64, |m, &x| m.max(x));
    let kept: Vec<usize> = (0..width).filter(|&c| norms[c] > 1e-12 * largest).collect();
    let m = nalgebra::DMatrix::from_fn(rows.len(), kept.len(), |i, j| {
        rows[i][kept[j]] / norms[kept[j]]
    });
    let singular = m.singular_values();
    let largest = singular.max();
    singular.iter().filter(|&&s| s > 1e-9 * largest).count()
}

#[test]
fn the_mimic_pandas_base_parameters_are_the_rank_of_pinocchios_projected_regressor() {
    let (robot, mut eq) = panda();
    // The links' parameters only, as Pinocchio's regressor has them.
    let joints = vec![JointColumns::default(); robot.joints.len()];
    let base = eq.base_parameters(&robot, &joints).expect("numbers");
    let file = data();
    let samples = file["samples"].as_array().expect("samples");
    let mut stacked = Vec::new();
    let mut worst: f64 = 0.0;
    for sample in samples {
        let y = numbers(&sample["Y"]);
        stacked.extend(y.chunks(90).map(<[f64]>::to_vec));
        let values = at(&eq, sample);
        let pi_b = values.vector(&base.values);
        let tau: Vec<f64> = (base.regressor.iter())
            .map(|row| dot(&values.vector(row), &pi_b))
            .collect();
        worst = worst.max(scaled_error(&tau, &numbers(&sample["tau"])));
    }
    let rank = rank(&stacked);
    assert!(2 * rank < stacked.len(), "too few rows for the rank");
    println!(
        "mimic Panda: {} base parameters, rank {rank}; Y_B π_B against τ: {worst:.1e}",
        base.parameters.len()
    );
    assert_eq!(base.parameters.len(), rank);
    assert!(worst < TOLERANCE, "{worst:e}");
}
