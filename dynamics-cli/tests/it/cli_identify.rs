//! `dynamics identify` end to end, on data synthesised from a robot with known parameters
//! (`synthetic`: torques from the numeric inverse dynamics, not from the regressor under test);
//! the predictions the tests check are the reduced regressor's graph evaluated by `Graph::eval`,
//! not by the tape `identify` uses.

use crate::synthetic;

use dynamics_codegen::model::Robot;
use dynamics_codegen::symbolic::Var;
use dynamics_codegen::trace::base_parameters::{BaseParameters, JointColumns};
use dynamics_codegen::{derive, Equations};
use serde_json::Value;
use std::fmt::Write as _;
use synthetic::{
    arm, arm_file_static, dynamics, fourier, json, normal, scratch, torques, write_csv, State,
};

const ALL_TERMS: [&str; 3] = ["--rotors", "--friction", "viscous,coulomb,offset"];

/// One parameter's estimate, as the report gives it.
struct Estimate {
    name: String,
    value: f64,
    deviation: f64,
}

/// The estimates by name.
fn estimates(report: &Value) -> Vec<Estimate> {
    let parameters = report["parameters"].as_array().expect("parameters");
    parameters
        .iter()
        .map(|p| Estimate {
            name: p["name"].as_str().expect("name").to_string(),
            value: p["estimate"].as_f64().expect("a number"),
            deviation: p["std_dev"].as_f64().expect("a number"),
        })
        .collect()
}

/// τ predicted by the estimates at `s`: the reduced regressor's columns of the named base
/// parameters, the graph evaluated whole.
fn predict(eq: &Equations, base: &BaseParameters, estimates: &[Estimate], s: &State) -> Vec<f64> {
    let values = eq.graph.eval(|v| match v {
        Var::Q(i) => s.q[usize::from(i)],
        Var::SinQ(i) => s.q[usize::from(i)].sin(),
        Var::CosQ(i) => s.q[usize::from(i)].cos(),
        Var::Qd(i) => s.qd[usize::from(i)],
        Var::Qdd(i) => s.qdd[usize::from(i)],
        _ => f64::NAN,
    });
    (0..eq.dof)
        .map(|i| {
            let terms = estimates.iter().map(|e| {
                let b = base.parameters.iter().position(|p| p.name == e.name);
                values[base.regressor[i][b.expect("a base parameter")].index()] * e.value
            });
            terms.sum()
        })
        .collect()
}

/// The equations of the arm and its base parameters with every joint term.
fn base_parameters(robot: &Robot) -> (Equations, BaseParameters) {
    let mut eq = derive(robot);
    let every = JointColumns {
        actuator_inertia: true,
        viscous: true,
        coulomb: true,
        offset: true,
    };
    let base = eq
        .base_parameters(robot, &[every; 4])
        .expect("numbers only");
    (eq, base)
}

/// The largest difference over the samples, relative to the largest torque.
fn worst(predicted: &[Vec<f64>], measured: &[Vec<f64>]) -> f64 {
    let scale = measured
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = predicted.iter().flatten().zip(measured.iter().flatten());
    diff.fold(0.0f64, |m, (p, t)| m.max((p - t).abs())) / scale
}

/// The spring torque of joint 2, which the measured torques hold and the regressor does not.
fn without_spring(tau: &[f64], s: &State) -> Vec<f64> {
    let mut out = tau.to_vec();
    out[1] -= 12.0 * (s.q[1] - 0.2);
    out
}

#[test]
fn noise_free_data_are_reproduced_and_predict_another_trajectory() {
    let robot = arm();
    let states = fourier(4, 1500, 100.0, 0.7, &[]);
    let tau = torques(&robot, &states, |_| 0.0);
    let csv = write_csv("exact.csv", &states, &tau, true);
    let svg = scratch("exact.svg");
    let svg = svg.to_str().unwrap();
    let _ = std::fs::remove_file(svg);
    let mut args = vec!["identify", arm_file_static(), "--csv", &csv, "--json"];
    args.extend(ALL_TERMS);
    args.extend(["--plot", svg]);
    let report = json(&dynamics(&args));
    assert_eq!(report["samples"].as_u64(), Some(1500));
    // The figure: a panel per joint of the measured and predicted torque, one of the residual.
    let figure = std::fs::read_to_string(svg).expect("the figure is written");
    for text in [
        "joint 1: τ1 (N m)",
        "joint 4: τ4 (N)",
        "joint 4: measured − predicted (N)",
    ] {
        assert!(figure.contains(text), "{text}");
    }
    assert_eq!(figure.matches("<polyline").count(), 4 * 3);
    assert_eq!(report["springs_subtracted"].as_bool(), Some(true));
    let scale = tau.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for joint in report["joints"].as_array().unwrap() {
        let rms = joint["residual_rms"].as_f64().unwrap();
        assert!(rms < 1e-9 * scale, "{joint}");
    }
    // Another trajectory, never seen by the fit: Y π̂ against the numeric inverse dynamics.
    let (eq, base) = base_parameters(&robot);
    let found = estimates(&report);
    assert_eq!(found.len(), base.parameters.len());
    let other = fourier(4, 200, 50.0, 2.3, &[]);
    let truth: Vec<Vec<f64>> = torques(&robot, &other, |_| 0.0)
        .iter()
        .zip(&other)
        .map(|(t, s)| without_spring(t, s))
        .collect();
    let predicted: Vec<Vec<f64>> = other
        .iter()
        .map(|s| predict(&eq, &base, &found, s))
        .collect();
    let error = worst(&predicted, &truth);
    assert!(error < 1e-9, "{error}");
    // The same from the command: --validate on that trajectory's file (springs included; the
    // command subtracts them, as in the fit).
    let other_tau = torques(&robot, &other, |_| 0.0);
    let other_csv = write_csv("other.csv", &other, &other_tau, true);
    let validation_svg = scratch("other.svg");
    let validation_svg = validation_svg.to_str().unwrap();
    let mut validate = args.clone();
    validate.extend(["--validate", &other_csv, "--validate-plot", validation_svg]);
    let validated = json(&dynamics(&validate));
    let v = &validated["validation"];
    assert_eq!(v["samples"].as_u64(), Some(200));
    for (i, joint) in v["joints"].as_array().expect("joints").iter().enumerate() {
        let rms = (truth.iter().map(|t| t[i] * t[i]).sum::<f64>() / 200.0).sqrt();
        let reported = joint["rms"].as_f64().unwrap();
        assert!((reported - rms).abs() < 1e-12 * rms, "{joint}: {rms}");
        assert!(
            joint["error_rms"].as_f64().unwrap() < 1e-9 * scale,
            "{joint}"
        );
    }
    let figure = std::fs::read_to_string(validation_svg).expect("the figure is written");
    assert!(figure.contains("predicted") && figure.contains("joint 4: τ4 (N)"));
    // Through the filters, τ and the regressor's columns are smoothed alike, Coulomb friction's
    // steps included: what is left is the low-pass's effect on q (and near the ends).
    args.extend(["--cutoff", "10"]);
    let filtered = json(&dynamics(&args));
    assert!(residual(&filtered) < 1e-6 * scale, "{filtered}");
}

/// The names of the parameters reported as not identifiable.
fn unidentifiable(report: &Value) -> Vec<String> {
    let list = report["unidentifiable"].as_array().expect("a list");
    list.iter()
        .map(|u| u["name"].as_str().expect("name").to_string())
        .collect()
}

/// Joint 3 held still: the terms it alone excites are named, with no estimate, and the rest
/// still reproduce the torques.
#[test]
fn a_joint_that_never_moves_names_what_it_leaves_unidentified() {
    let robot = arm();
    let states = fourier(4, 800, 100.0, 0.9, &[2]);
    let tau = torques(&robot, &states, |_| 0.0);
    // Positions only: the derivatives of a still joint come out exactly zero.
    let csv = write_csv("still.csv", &states, &tau, false);
    let mut args = vec!["identify", arm_file_static(), "--csv", &csv, "--json"];
    args.extend(ALL_TERMS);
    let report = json(&dynamics(&args));
    let named = unidentifiable(&report);
    // Columns q̈_3, q̇_3, sign(q̇_3) of joint 3's actuator and friction are zero in these data.
    for name in ["IA3", "FV3", "FC3"] {
        assert!(named.iter().any(|n| n == name), "{name}: {named:?}");
        let u = &report["unidentifiable"][named.iter().position(|n| n == name).unwrap()];
        assert_eq!(u["combination"].as_array().map(Vec::len), Some(0), "{u}");
    }
    let found = estimates(&report);
    let finite = |e: &Estimate| e.value.is_finite() && e.deviation.is_finite();
    assert!(found.iter().all(|e| finite(e) && !named.contains(&e.name)));
    // Estimated from differences, so to their accuracy: (ω h)² / 12 of the acceleration.
    let scale = tau.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for joint in report["joints"].as_array().unwrap() {
        assert!(
            joint["residual_rms"].as_f64().unwrap() < 1e-3 * scale,
            "{joint}"
        );
    }
}

#[test]
fn bad_csv_lines_are_named_by_line_and_column() {
    let robot = arm_file_static();
    let cases = [
        (
            "t,q1,q2,q3,q4,tau1,tau2,tau3,tau4\n0,0,0,0,0,1,2,3,4\n# a comment\n1,0,0,x,0,1,2,3,4\n",
            "line 4, column 4 (q3): `x` is not a number",
        ),
        (
            "t,q1,q2,q3,q4\n0,0,0,0,0\n",
            "line 1: the header has 5 columns; the robot has 4 joints",
        ),
        (
            "t,q1,q2,q3,q4,tau1,tau2,tau3,tau\n",
            "line 1, column 9 (tau): expected the header name `tau4`",
        ),
        (
            "t,q1,q2,q3,q4,tau1,tau2,tau3,tau4\n0,0,0,0,0,1,2,3,4\n1,0,0,0,0,1,2,3\n",
            "line 3, column 9 (tau4): 8 values; the header has 9 columns",
        ),
    ];
    for (k, (text, message)) in cases.iter().enumerate() {
        let csv = scratch(&format!("bad{k}.csv"));
        std::fs::write(&csv, text).unwrap();
        let out = dynamics(&["identify", robot, "--csv", csv.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(1), "{text}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{stderr}");
    }
}

/// The worst residual RMS over the joints of a report.
fn residual(report: &Value) -> f64 {
    let joints = report["joints"].as_array().expect("joints");
    joints
        .iter()
        .map(|j| j["residual_rms"].as_f64().expect("a number"))
        .fold(0.0, f64::max)
}

/// Positions with 10⁻⁴ rad (or m) of measurement noise: differenced twice at 200 Hz, the noise
/// reaches q̈ amplified by about 200² · √6; the zero-phase low-pass at 10 Hz (the motion's
/// highest harmonic is 1 Hz) takes most of it out before differentiation.
#[test]
fn a_low_pass_before_differentiation_tames_noisy_positions() {
    let robot = arm();
    let mut states = fourier(4, 3000, 200.0, 0.4, &[]);
    let tau = torques(&robot, &states, |_| 0.0);
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    for s in &mut states {
        for q in &mut s.q {
            // Uniform in ±√3 · 10⁻⁴: a standard deviation of 10⁻⁴.
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            *q += 3f64.sqrt() * 1e-4 * (2.0 * (seed >> 11) as f64 / (1u64 << 53) as f64 - 1.0);
        }
    }
    let csv = write_csv("noisy_q.csv", &states, &tau, false);
    let mut args = vec!["identify", arm_file_static(), "--csv", &csv, "--json"];
    args.extend(ALL_TERMS);
    let raw = json(&dynamics(&args));
    args.extend(["--cutoff", "10"]);
    let filtered = json(&dynamics(&args));
    assert_eq!(filtered["filter"]["cutoff_hz"].as_f64(), Some(10.0));
    assert_eq!(
        filtered["filter"]["rate_hz"].as_f64().map(f64::round),
        Some(200.0)
    );
    // Decimated to one sample in d = ⌊0.4 · 200 / 10⌋ = 8 once a window of 16 d + 1 = 129
    // samples is full: (3000 − 129) / 8 + 1 of them.
    assert_eq!(filtered["filter"]["decimation"].as_u64(), Some(8));
    assert_eq!(filtered["samples"].as_u64(), Some(359));
    assert_eq!(filtered["filter"]["samples_read"].as_u64(), Some(3000));
    assert!(raw["filter"].is_null());
    let (before, after) = (residual(&raw), residual(&filtered));
    assert!(after < 0.05 * before, "{after} {before}");
    // The text says which filter ran.
    args.retain(|a| *a != "--json");
    let text = String::from_utf8(dynamics(&args).stdout).unwrap();
    for words in [
        "4th-order Butterworth low-pass at 10 Hz",
        "τ and every column of the regressor alike: a zero-phase FIR low-pass (129 taps)",
        "one sample in 8 kept, 359 of 3000",
    ] {
        assert!(text.contains(words), "{text}");
    }
}

#[test]
fn a_filter_needs_even_samples() {
    let csv = scratch("uneven.csv");
    let mut text = String::from("t,q1,q2,q3,q4,tau1,tau2,tau3,tau4\n");
    for t in [0.0, 0.01, 0.02, 0.035, 0.04, 0.05] {
        let _ = writeln!(text, "{t},0,0,0,0,1,2,3,4");
    }
    std::fs::write(&csv, text).unwrap();
    let csv = csv.to_str().unwrap();
    let out = dynamics(&["identify", arm_file_static(), "--csv", csv, "--cutoff", "5"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("line 5, column 1 (t): --cutoff needs evenly spaced samples"),
        "{stderr}"
    );
}

/// A cutoff whose filter's window is longer than the file is a usage error that says so, with
/// the smallest cutoff that fits: 1001 samples at 100 Hz hold a window of `16 d + 1` samples
/// for d ≤ 62, so `d = ⌊0.4 · 100 / f_c⌋ ≤ 62` needs `f_c > 40 / 63 = 0.6349` Hz: 0.635 Hz.
/// (`--cutoff 1e-5` asked for a window of 6.4·10⁷ samples and aborted allocating it.)
#[test]
fn a_cutoff_whose_window_is_longer_than_the_file_is_refused() {
    let states = fourier(4, 1001, 100.0, 0.4, &[]);
    let tau = torques(&arm(), &states, |_| 0.0);
    let csv = write_csv("short_for_the_cutoff.csv", &states, &tau, true);
    let run = |cutoff: &str| {
        let out = dynamics(&[
            "identify",
            arm_file_static(),
            "--csv",
            &csv,
            "--cutoff",
            cutoff,
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        (out.status.code(), stderr)
    };
    let (code, stderr) = run("1e-5");
    assert_eq!(code, Some(2), "{stderr}");
    for words in [
        "--cutoff 1e-5: for samples at 100.0 Hz its filter keeps one sample in ",
        "samples (16 d + 1, d = ⌊0.4 f_s / f_c⌋), more than the 1001 samples of ",
        "the smallest cutoff whose window fits is 0.635 Hz",
    ] {
        assert!(stderr.contains(words), "{stderr}");
    }
    // d = ⌊40 / 0.634⌋ = 63: 1009 samples.
    let (code, stderr) = run("0.634");
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("a window of 1009 samples"), "{stderr}");
    // d = 62: 993 samples, one of them kept, too few for the fit, which says so.
    let (code, stderr) = run("0.635");
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("(--cutoff 0.635 keeps one sample in 62: 1 of the 1001 samples)"),
        "{stderr}"
    );
}

/// Torques with noise of a different level on each joint (exact q̇, q̈): every estimate within
/// four of its standard deviations of the description's base parameter, and the weights
/// found near the noise put in.
#[test]
fn noisy_torques_give_estimates_within_their_standard_deviations() {
    let robot = arm();
    let states = fourier(4, 4000, 100.0, 1.3, &[]);
    let levels = [0.05, 0.2, 0.02, 0.1];
    let mut seed = 0x853c_49e6_748f_ea9b_u64;
    let tau = torques(&robot, &states, |j| levels[j] * normal(&mut seed));
    let csv = write_csv("noisy_tau.csv", &states, &tau, true);
    let mut args = vec!["identify", arm_file_static(), "--csv", &csv, "--json"];
    args.extend(ALL_TERMS);
    let report = json(&dynamics(&args));
    assert!(unidentifiable(&report).is_empty(), "{report}");
    let (eq, base) = base_parameters(&robot);
    // The description's base parameters, the graph evaluated whole (no joint variables).
    let all = eq.graph.eval(|_| f64::NAN);
    let found = estimates(&report);
    let mut chi2 = 0.0;
    for e in &found {
        let b = base.parameters.iter().position(|p| p.name == e.name);
        let truth = all[base.values[b.expect("a base parameter")].index()];
        let error = (e.value - truth).abs();
        chi2 += (error / e.deviation).powi(2);
        assert!(
            error < 4.0 * e.deviation,
            "{}: {} ± {} against {truth}",
            e.name,
            e.value,
            e.deviation
        );
    }
    // Nor are the deviations inflated: the normalised squared errors average near 1 (a χ² of
    // 33 degrees of freedom over 33 is within 0.3 and 2.5 but once in 10⁴).
    let mean = chi2 / found.len() as f64;
    assert!(mean > 0.3 && mean < 2.5, "{mean}");
    for (joint, level) in report["joints"].as_array().unwrap().iter().zip(levels) {
        let sigma = joint["sigma"].as_f64().unwrap();
        assert!((sigma / level - 1.0).abs() < 0.05, "{joint}: {level}");
    }
}

/// 0.4 s of motion, too short to excite everything: joint 1 turns one way only, so its Coulomb
/// column `sign(q̇_1)` is the constant −1 and its offset column 1 is minus it; such parameters
/// are named with their combination, and the others still fit the torques.
#[test]
fn too_little_excitation_names_what_it_cannot_separate() {
    let robot = arm();
    let states = fourier(4, 40, 100.0, 0.7, &[]);
    assert!(states.iter().all(|s| s.qd[0] < 0.0));
    let tau = torques(&robot, &states, |_| 0.0);
    let csv = write_csv("short.csv", &states, &tau, true);
    let mut args = vec!["identify", arm_file_static(), "--csv", &csv, "--json"];
    args.extend(ALL_TERMS);
    let report = json(&dynamics(&args));
    let named = unidentifiable(&report);
    let at = named.iter().position(|n| n == "FO1").expect("FO1 named");
    let combination = &report["unidentifiable"][at]["combination"];
    assert_eq!(combination[0]["name"], "FC1", "{combination}");
    assert!((combination[0]["coefficient"].as_f64().unwrap() + 1.0).abs() < 1e-9);
    assert!(estimates(&report).iter().all(|e| !named.contains(&e.name)));
    let scale = tau.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(residual(&report) < 1e-4 * scale, "{report}");
}
