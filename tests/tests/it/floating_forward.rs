//! The forward dynamics and `M⁻¹` of a robot on a free-flying base, and their nalgebra and
//! batch forms: Solo 12 against Pinocchio 4.1's `aba` and `computeMinverse`
//! (`tests/data/floating/solo12.json`, by `make.py`), to 1e-12 scaled; ANYmal B and the G1
//! (whose forward dynamics is the articulated-body algorithm's) against the `aba` and `Minv`
//! of their `*_derivatives.json`.

use super::floating_base::{array, flat, numbers, reference, AnymalB, Solo12, G1, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{FloatingDynamics, FloatingDynamicsBatch, NotPositiveDefinite};

fn samples() -> Vec<serde_json::Value> {
    reference("solo12")["samples"]
        .as_array()
        .expect("samples")
        .clone()
}

#[test]
fn forward_dynamics_and_inverse_mass_against_pinocchio() {
    let samples = samples();
    assert!(samples.len() >= 10);
    for (k, s) in samples.iter().enumerate() {
        let (q, v, tau) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["tau_in"]),
        );
        let a = Solo12
            .forward_dynamics(&q, &v, &tau)
            .expect("M is positive definite");
        let error = scaled_error(&a, &numbers(&s["a_fd"]));
        assert!(error < TOLERANCE, "sample {k}: aba off by {error:e}");
        let inverse = Solo12
            .mass_matrix_inverse(&q)
            .expect("M is positive definite");
        let got: Vec<f64> = inverse.iter().flatten().copied().collect();
        let error = scaled_error(&got, &flat(&s["M_inv"]));
        assert!(error < TOLERANCE, "sample {k}: M⁻¹ off by {error:e}");
        // The inverse of inverse dynamics: τ(q, v, a(τ)) = τ.
        let back = Solo12.inverse_dynamics(&q, &v, &a);
        let error = scaled_error(&back, &tau);
        assert!(error < TOLERANCE, "sample {k}: rnea(aba) off by {error:e}");
    }
}

/// The batch form gives each state's scalar result, bit for bit, and a state whose M is not
/// positive definite (a NaN joint angle: a NaN pivot) is reported, not computed.
#[test]
fn batch_form_agrees_with_the_scalar_calls() {
    let samples = samples();
    let mut q: Vec<[f64; 19]> = samples.iter().map(|s| array(&s["q"])).collect();
    let v: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["v"])).collect();
    let tau: Vec<[f64; 18]> = samples.iter().map(|s| array(&s["tau_in"])).collect();
    q[5][8] = f64::NAN;
    let mut out = vec![Ok([0.0; 18]); q.len()];
    Solo12.forward_dynamics_batch(&q[..], &v[..], &tau[..], &mut out[..]);
    for (k, got) in out.iter().enumerate() {
        let expected = Solo12.forward_dynamics(&q[k], &v[k], &tau[k]);
        match (got, expected) {
            (Ok(a), Ok(b)) => {
                let bits = |x: &[f64; 18]| x.map(f64::to_bits);
                assert_eq!(bits(a), bits(&b), "state {k}");
            }
            (Err(NotPositiveDefinite), Err(NotPositiveDefinite)) => assert_eq!(k, 5),
            (a, b) => panic!("state {k}: {a:?} against {b:?}"),
        }
    }
    assert!(out[5].is_err());
}

/// `integrate`, `difference` and `∂ integrate / ∂v` against Pinocchio's, sample #1's step a
/// rotation of 1e-9 rad (the Taylor branch), the others up to 2.6 rad.
#[test]
fn configuration_space_against_pinocchio() {
    for (k, s) in samples().iter().enumerate() {
        let (q, dv, q1) = (
            array::<19>(&s["q"]),
            array::<18>(&s["dv"]),
            array::<19>(&s["q1"]),
        );
        let moved = Solo12.integrate(&q, &dv);
        let error = scaled_error(&moved, &numbers(&s["q_next"]));
        assert!(error < TOLERANCE, "sample {k}: integrate off by {error:e}");
        let d = Solo12.difference(&q, &q1);
        let error = scaled_error(&d, &numbers(&s["dq"]));
        assert!(error < TOLERANCE, "sample {k}: difference off by {error:e}");
        let j: Vec<f64> = Solo12
            .integrate_jacobian_v(&q, &dv)
            .iter()
            .flatten()
            .copied()
            .collect();
        let error = scaled_error(&j, &flat(&s["dintegrate_dv"]));
        assert!(
            error < TOLERANCE,
            "sample {k}: dIntegrate/dv off by {error:e}"
        );
    }
}

/// `∂ integrate / ∂q` and `∂ difference / ∂q0`, `∂q1` against Pinocchio's `dIntegrate(.., ARG0)`
/// and `dDifference(.., ARG0 / ARG1)`, at the same states (sample #1's step the Taylor branch;
/// `q1` an independent random state, rotations up to π away).
#[test]
fn configuration_jacobians_against_pinocchio() {
    fn rows(m: [[f64; 18]; 18]) -> Vec<f64> {
        m.iter().flatten().copied().collect()
    }
    for (k, s) in samples().iter().enumerate() {
        let (q, dv, q1) = (
            array::<19>(&s["q"]),
            array::<18>(&s["dv"]),
            array::<19>(&s["q1"]),
        );
        let found = [
            ("dintegrate_dq", rows(Solo12.integrate_jacobian_q(&q, &dv))),
            (
                "ddifference_dq0",
                rows(Solo12.difference_jacobian_q0(&q, &q1)),
            ),
            (
                "ddifference_dq1",
                rows(Solo12.difference_jacobian_q1(&q, &q1)),
            ),
        ];
        for (key, j) in found {
            let error = scaled_error(&j, &flat(&s[key]));
            assert!(error < TOLERANCE, "sample {k}: {key} off by {error:e}");
        }
    }
}

/// `forward_dynamics` at the derivatives' data's `tau_in` against Pinocchio's
/// `aba(q, v, tau_in)` (`ddq`) to [`TOLERANCE`] and `mass_matrix_inverse` against its `Minv`
/// (`ddq_dtau`) to `inverse_tolerance`, at the states of `name`'s data; returns the largest
/// errors.
fn against_aba<R: FloatingDynamics<Q, V>, const Q: usize, const V: usize>(
    robot: &R,
    name: &str,
    inverse_tolerance: f64,
) -> [f64; 2] {
    let states = reference(name)["samples"].clone();
    let data = reference(&format!("{name}_derivatives"));
    let samples = data["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    let mut worst = [0.0_f64; 2];
    for (k, d) in samples.iter().enumerate() {
        let (q, v) = (array::<Q>(&states[k]["q"]), array::<V>(&states[k]["v"]));
        let tau = array::<V>(&d["tau_in"]);
        let a = robot.forward_dynamics(&q, &v, &tau).expect("M");
        let error = scaled_error(&a, &numbers(&d["ddq"]));
        assert!(error < TOLERANCE, "{name} sample {k}: aba off by {error:e}");
        let inverse = robot.mass_matrix_inverse(&q).expect("M");
        let got: Vec<f64> = inverse.iter().flatten().copied().collect();
        let inverse_error = scaled_error(&got, &flat(&d["ddq_dtau"]));
        assert!(
            inverse_error < inverse_tolerance,
            "{name} sample {k}: M⁻¹ off by {inverse_error:e}"
        );
        worst = [worst[0].max(error), worst[1].max(inverse_error)];
    }
    worst
}

#[test]
fn anymal_b_forward_dynamics_against_pinocchio() {
    let [a, inverse] = against_aba(&AnymalB, "anymal_b", TOLERANCE);
    eprintln!("ANYmal B: largest scaled errors a {a:e}, M⁻¹ {inverse:e}");
}

/// The G1 (35 coordinates): its forward dynamics is the articulated-body algorithm's, as
/// Pinocchio's `aba` (6.6e-15 from it); its M⁻¹ the LDLᵀ's, to 1e-11: M's condition number
/// reaches 3.5e5 at these states (`floating_derivatives.rs`), and the two factorizations
/// round differently (8.9e-13 here).
#[test]
fn g1_forward_dynamics_against_pinocchio() {
    let [a, inverse] = against_aba(&G1, "g1_29dof", 1e-11);
    eprintln!("G1: largest scaled errors a {a:e}, M⁻¹ {inverse:e}");
}
