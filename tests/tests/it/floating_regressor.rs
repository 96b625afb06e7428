//! The joint torque regressor and the base parameters of robots on a free-flying base
//! (`regressor = true`, `base_parameters = true`): Solo 12 and ANYmal B against Pinocchio 4.1's
//! `computeJointTorqueRegressor` on the free flyer (`tests/data/floating/*_regressor.json`, by
//! `make.py`, which checks `Y π = rnea` first) to 1e-12 scaled, the standard parameters against
//! Pinocchio's `toDynamicParameters`, `Y π` and `Y_B π_B` against the generated
//! `inverse_dynamics`, the number of base parameters against the numerical rank of Pinocchio's
//! stacked regressor; the batch forms against the plain calls.

use super::floating_base::{array, numbers, reference};
use dynamics_reference::scaled_error;
use dynamics_runtime::{
    FloatingDynamicsBaseParameters, FloatingDynamicsBaseParametersBatch, FloatingDynamicsRegressor,
    FloatingDynamicsRegressorBatch,
};

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating,
    regressor = true,
    base_parameters = true
)]
struct Solo12;

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/anymal_b.urdf",
    base = floating,
    regressor = true,
    base_parameters = true
)]
struct AnymalB;

/// The bar: 1e-12, scaled by max(1, the largest element).
const TOLERANCE: f64 = 1e-12;

fn regressor_data(robot: &str) -> serde_json::Value {
    let path = format!(
        "{}/data/floating/{robot}_regressor.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).expect("json")
}

/// `Σ_j Σ_k y[i][j][k] π[j][k]`, row by row.
fn times<const V: usize, const L: usize>(y: &[[[f64; 10]; L]; V], pi: &[[f64; 10]; L]) -> Vec<f64> {
    y.iter()
        .map(|row| {
            let terms = row.iter().zip(pi).flat_map(|(a, b)| a.iter().zip(b));
            terms.map(|(a, b)| a * b).sum()
        })
        .collect()
}

/// The regressor and the base parameters of `robot` at every sample of `name`'s data: `Y`
/// against Pinocchio's, `π` against its parameters, `Y π` and `Y_B π_B` against the
/// generated τ and the data's. Returns the largest errors of `Y`, `Y π` and `Y_B π_B`.
fn against_pinocchio<R, const Q: usize, const V: usize, const L: usize, const B: usize>(
    robot: &R,
    name: &str,
) -> [f64; 3]
where
    R: FloatingDynamicsRegressor<Q, V, L> + FloatingDynamicsBaseParameters<Q, V, B, L>,
{
    let data = regressor_data(name);
    let states = reference(name);
    let pi = robot.standard_parameters();
    let flat_pi: Vec<f64> = pi.iter().flatten().copied().collect();
    let error = scaled_error(&flat_pi, &numbers(&data["pi"]));
    assert!(error < TOLERANCE, "{name}: π off by {error:e}");
    // The numerical rank of Pinocchio's stacked regressor: the identifiable combinations.
    assert_eq!(data["rank"].as_u64(), Some(B as u64), "{name}: B");
    let pi_b: [f64; B] = robot.base_parameters();
    let map: [[[f64; 10]; L]; B] = robot.base_from_standard();
    for (b, row) in map.iter().enumerate() {
        let mapped: f64 = row
            .iter()
            .zip(&pi)
            .flat_map(|(p, x)| p.iter().zip(x))
            .map(|(p, x)| p * x)
            .sum();
        assert!(
            (mapped - pi_b[b]).abs() <= 1e-12 * pi_b[b].abs().max(1.0),
            "{name}: π_B[{b}]"
        );
    }
    let mut worst = [0.0_f64; 3];
    let samples = data["samples"].as_array().expect("samples");
    let state_samples = states["samples"].as_array().expect("samples");
    for (k, (s, state)) in samples.iter().zip(state_samples).enumerate() {
        let q: [f64; Q] = array(&state["q"]);
        let (v, a): ([f64; V], [f64; V]) = (array(&state["v"]), array(&state["a"]));
        let y = robot.regressor(&q, &v, &a);
        let got: Vec<f64> = y.iter().flatten().flatten().copied().collect();
        let want: Vec<f64> = s["Y"]
            .as_array()
            .expect("Y")
            .iter()
            .flat_map(numbers)
            .collect();
        let tau = robot.inverse_dynamics(&q, &v, &a);
        let y_pi = times(&y, &pi);
        let yb = robot.base_regressor(&q, &v, &a);
        let yb_pi: Vec<f64> = yb
            .iter()
            .map(|row| row.iter().zip(&pi_b).map(|(x, p)| x * p).sum())
            .collect();
        let errors = [
            scaled_error(&got, &want),
            scaled_error(&y_pi, &tau),
            scaled_error(&yb_pi, &tau),
        ];
        assert!(
            errors.iter().all(|&e| e < TOLERANCE),
            "{name} sample {k}: {errors:?}"
        );
        assert!(scaled_error(&tau, &numbers(&state["tau"])) < TOLERANCE);
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    worst
}

#[test]
fn solo12_against_pinocchio() {
    let worst = against_pinocchio(&Solo12, "solo12");
    eprintln!("solo12: Y, Y π, Y_B π_B within {worst:?}");
}

#[test]
fn anymal_b_against_pinocchio() {
    let worst = against_pinocchio(&AnymalB, "anymal_b");
    eprintln!("anymal_b: Y, Y π, Y_B π_B within {worst:?}");
}

/// Every body's ten parameters reach the generalized forces, the floating body's included: no
/// column block of `Y` is zero throughout, and the floating body's ten are base parameters of
/// their own (the base's six rows are the whole robot's Newton-Euler equations).
#[test]
fn the_floating_body_is_identifiable() {
    let states = reference("solo12");
    let s = &states["samples"][3];
    let q: [f64; 19] = array(&s["q"]);
    let (v, a): ([f64; 18], [f64; 18]) = (array(&s["v"]), array(&s["a"]));
    let y = Solo12.regressor(&q, &v, &a);
    for k in 0..10 {
        assert!(
            y.iter().any(|row| row[0][k] != 0.0),
            "floating body's column {k}"
        );
    }
    // The first ten base parameters are the floating body's own, each with coefficient 1 on it.
    let map: [[[f64; 10]; 13]; 94] = Solo12.base_from_standard();
    for (k, row) in map.iter().take(10).enumerate() {
        let own = row[0].iter().filter(|&&c| c != 0.0).count();
        assert_eq!(own, 1, "base parameter {k}");
    }
}

/// The batch and `_into` forms give the plain calls' numbers (the nalgebra forms are the
/// table's wrappers, as a fixed base's).
#[test]
fn batch_forms() {
    let states = reference("solo12");
    let samples = states["samples"].as_array().expect("samples");
    let q: Vec<[f64; 19]> = samples.iter().map(|s| array(&s["q"])).collect();
    let v: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["v"])).collect();
    let a: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["a"])).collect();
    let mut y = vec![[[[0.0; 10]; 13]; 18]; q.len()];
    Solo12.regressor_batch(&q[..], &v[..], &a[..], &mut y[..]);
    let mut yb = vec![[[0.0; 94]; 18]; q.len()];
    Solo12.base_regressor_batch(&q[..], &v[..], &a[..], &mut yb[..]);
    for k in 0..q.len() {
        let single = Solo12.regressor(&q[k], &v[k], &a[k]);
        assert_eq!(y[k], single, "regressor_batch, state {k}");
        assert_eq!(
            yb[k],
            Solo12.base_regressor(&q[k], &v[k], &a[k]),
            "base, state {k}"
        );
    }
    let mut into = [[[1.0; 10]; 13]; 18];
    Solo12.regressor_into(&q[2], &v[2], &a[2], &mut into);
    assert_eq!(into, y[2]);
}
