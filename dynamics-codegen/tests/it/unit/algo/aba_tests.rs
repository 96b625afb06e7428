//! The articulated-body algorithm on a floating base (`algo::floating_aba`) against the
//! composite bodies' `M` and Newton-Euler's `h` on hand-built trees (revolute and prismatic
//! joints, γ and b, frame 0 turned and shifted on the base), with armature, and against
//! Pinocchio's `aba` on the G1 (`tests/data/floating/g1_29dof_derivatives.json`).

use crate::unit::algo::floating_tests::{numeric_base, urdf_robot};
use crate::unit::algo::tree_tests::{at, chain, robot, trees, R};
use dynamics_codegen::algo::{
    floating_aba, floating_crba, floating_rnea, FloatingBase, Inertial, Ldlt, Mat3, V3,
};

/// `M a + h = τ` for `a` by the articulated-body algorithm, the armature on M's diagonal; and
/// its pivots those of M's LDLᵀ from the tips (their product M's determinant, each positive).
#[test]
fn articulated_bodies_solve_m_a_plus_h() {
    let (sr, cr) = (0.6f64.sin(), 0.6f64.cos());
    let rotation = Mat3::rot_x(sr, cr).mul(&Mat3::rot_z(0.4f64.sin(), 0.4f64.cos()));
    let body = Inertial {
        mass: 2.0,
        com: V3::new(0.1, -0.2, 0.3),
        inertia: [0.3, 0.25, 0.2, 0.01, -0.02, 0.015],
    };
    let base = FloatingBase::new(&body, rotation, V3::new(0.2, -0.1, 0.05));
    let quaternion = [-0.2, 0.7, 0.1, 0.4].map(|x: f64| x / 0.7f64.sqrt());
    let gravity = V3::new(0.3, 0.0, -9.81);
    let mut specs = trees();
    specs.push(vec![at(None, R, 0.0, 0.0, 1.0)]);
    for (t, spec) in specs.iter().enumerate() {
        let robot = robot(spec, true);
        let n = robot.dof();
        let q: Vec<f64> = (0..n).map(|i| 0.3 + 0.7 * i as f64).collect();
        let c = chain(&robot, &q);
        let v: Vec<f64> = (0..n + 6).map(|i| (1.3 * i as f64).sin()).collect();
        let tau: Vec<f64> = (0..n + 6).map(|i| 3.0 * (0.9 * i as f64).cos()).collect();
        for armature in [0.0, 0.05] {
            let armature: Vec<f64> = (0..n).map(|i| armature * (1 + i % 2) as f64).collect();
            let got = floating_aba(&c, &base, quaternion, &v, &tau, &armature, gravity);
            let mut m = floating_crba(&c, &base);
            for (i, x) in armature.iter().enumerate() {
                m[6 + i][6 + i] += x;
            }
            let h = floating_rnea(&c, &base, quaternion, &v, &vec![0.0; n + 6], gravity);
            let a = &got.acceleration;
            let scale = tau.iter().fold(1.0f64, |x, e| x.max(e.abs()));
            for k in 0..n + 6 {
                let ma: f64 = (0..n + 6).map(|j| m[k][j] * a[j]).sum();
                let what = format!("tree {t}, armature {armature:?}: row {k}");
                assert!((ma + h[k] - tau[k]).abs() < 1e-12 * scale, "{what}");
            }
            let product = |p: &[f64]| p.iter().product::<f64>();
            let determinant = product(&Ldlt::from_the_tips(&m).pivots);
            let pivots = product(&got.pivots);
            assert!(got.pivots.iter().all(|&d| d > 0.0), "tree {t}: pivots");
            assert!(
                (pivots - determinant).abs() < 1e-10 * determinant,
                "tree {t}: det"
            );
        }
    }
}

/// The G1 (29 joints) against Pinocchio 4.1's `aba(q, v, tau_in)` at the 12 states of its
/// data, to 1e-10 scaled (M's condition reaches 3.5e5 there: `floating_derivatives.rs`).
#[test]
fn g1_against_pinocchio() {
    let (robot, flyer) = urdf_robot("g1_29dof");
    let base = numeric_base(&robot, &flyer);
    let read = |name: &str| -> serde_json::Value {
        let path = format!(
            "{}/../tests/data/floating/{name}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        serde_json::from_str(&std::fs::read_to_string(path).expect("the data")).expect("JSON")
    };
    let list = |x: &serde_json::Value| -> Vec<f64> {
        let numbers = x.as_array().expect("a list").iter();
        numbers.map(|e| e.as_f64().expect("a number")).collect()
    };
    let (states, data) = (read("g1_29dof"), read("g1_29dof_derivatives"));
    let samples = data["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    let armature = vec![0.0; 29];
    let gravity = V3::new(0.0, 0.0, -9.81);
    for (k, d) in samples.iter().enumerate() {
        let s = &states["samples"][k];
        let (q, v, tau) = (list(&s["q"]), list(&s["v"]), list(&d["tau_in"]));
        let c = chain(&robot, &q[7..]);
        let quaternion = [q[3], q[4], q[5], q[6]];
        let got = floating_aba(&c, &base, quaternion, &v, &tau, &armature, gravity);
        let expected = list(&d["ddq"]);
        let scale = expected.iter().fold(1.0f64, |x, e| x.max(e.abs()));
        for (i, (x, e)) in got.acceleration.iter().zip(&expected).enumerate() {
            assert!(
                (x - e).abs() <= 1e-10 * scale,
                "sample {k}, a[{i}]: {x} vs {e}"
            );
        }
    }
}
