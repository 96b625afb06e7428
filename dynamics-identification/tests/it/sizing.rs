//! The sizing's terms of τ against Pinocchio's, and its peaks.

use dynamics_codegen::{load, Source};
use dynamics_identification::sizing::terms::{At, TermsTape};
use dynamics_identification::sizing::Sizer;
use dynamics_identification::trajectory::Sample;
use serde_json::Value;

fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// The terms against Pinocchio's reference data of the PUMA 560: `M q̈` (no actuator inertia
/// in this model), `g`, and `C q̇ = τ − M q̈ − g`; the sizing's peaks, four samples at a time.
#[test]
fn terms_equal_pinocchio() {
    let path = root().join("robots/puma560.toml");
    let path = path.to_str().unwrap();
    let robot = load(&Source::file(path)).unwrap().robot;
    let eq = dynamics_codegen::derive(&robot);
    let mut tape = TermsTape::new(&robot, &eq, &[]).unwrap();
    let data: Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("tests/data/reference/data/puma560.json")).unwrap(),
    )
    .unwrap();
    let v = |x: &Value| -> Vec<f64> {
        x.as_array()
            .unwrap()
            .iter()
            .map(|y| y.as_f64().unwrap())
            .collect()
    };
    let samples: Vec<Sample> = data["samples"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .map(|(k, s)| Sample {
            t: k as f64,
            q: v(&s["q"]),
            qd: v(&s["qd"]),
            qdd: v(&s["qdd"]),
            tau: v(&s["tau"]),
            ..Sample::default()
        })
        .collect();
    for (s, data) in samples.iter().zip(data["samples"].as_array().unwrap()) {
        let m: Vec<Vec<f64>> = data["M"].as_array().unwrap().iter().map(v).collect();
        let g = v(&data["g"]);
        let at = At {
            q: &s.q,
            qd: &s.qd,
            qdd: &s.qdd,
        };
        let terms = &tape.terms(&[at])[0];
        for i in 0..6 {
            let inertial: f64 = (0..6).map(|k| m[i][k] * s.qdd[k]).sum();
            let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * (1.0 + b.abs());
            assert!(close(terms.inertial[i], inertial));
            assert!(close(terms.gravity[i], g[i]));
            assert!(close(terms.coriolis[i], s.tau[i] - inertial - g[i]));
            assert_eq!((terms.actuator[i], terms.friction[i]), (0.0, 0.0));
        }
    }
    // The sizing's peak is the largest |τ| over the samples (not a whole number of groups).
    let mut sizer = Sizer::new(&mut tape, 6, ());
    for s in &samples[..samples.len() - 1] {
        sizer.push(s);
    }
    sizer.finish();
    for i in 0..6 {
        let peak = samples[..samples.len() - 1]
            .iter()
            .map(|s| s.tau[i])
            .fold(0.0f64, |a, b| if b.abs() > a.abs() { b } else { a });
        assert!((sizer.joints[i].peak - peak).abs() < 1e-9 * (1.0 + peak.abs()));
    }
    assert_eq!(sizer.samples, samples.len() - 1);
}
