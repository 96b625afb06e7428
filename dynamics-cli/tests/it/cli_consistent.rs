//! `dynamics identify --consistent` end to end, on data synthesised from robots with known
//! parameters (`synthetic`): the consistent estimate equals the plain one where that is
//! physically consistent, and is consistent where the plain one is not.

use crate::synthetic;

use dynamics_codegen::derive;
use dynamics_codegen::model::Robot;
use dynamics_codegen::numeric::Numeric;
use dynamics_codegen::symbolic::Var;
use dynamics_codegen::trace::base_parameters::JointColumns;
use serde_json::Value;
use synthetic::{
    arm, arm_file_static, arm_text, dynamics, fourier, json, normal, scratch, torques, write_csv,
};

fn numbers(v: &Value, key: &str) -> Vec<f64> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x[key].as_f64().expect("a number"))
        .collect()
}

/// Every link's smallest pseudo-inertia eigenvalue, as reported.
fn smallest_eigenvalues(report: &Value) -> Vec<f64> {
    numbers(&report["consistent"]["links"], "smallest_eigenvalue")
}

const ALL_TERMS: [&str; 3] = ["--rotors", "--friction", "viscous,coulomb,offset"];

/// The description `written` by `--description-out` passes the checks (`dynamics inspect`
/// reads it), and its inverse dynamics (`Numeric`, spring and friction included, the spring
/// taken off) equals `Y_B π_B` of the consistent estimate in `report`, the base regressor of
/// `robot` evaluated by `Graph::eval`, to 10⁻⁹ of the largest torque, along another motion.
fn check_written(robot: &Robot, written: &str, report: &Value) {
    let out = dynamics(&["inspect", written]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(written).expect("written");
    let loaded = dynamics_codegen::front::load(written, &text)
        .expect("reads")
        .robot;
    let numeric = Numeric::new(&loaded, &[]).expect("no fields");
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
    let estimates = &report["consistent"]["parameters"];
    let mut worst = 0.0f64;
    let mut largest = 0.0f64;
    for s in &fourier(4, 300, 100.0, 2.1, &[]) {
        let values = eq.graph.eval(|v| match v {
            Var::Q(i) => s.q[usize::from(i)],
            Var::SinQ(i) => s.q[usize::from(i)].sin(),
            Var::CosQ(i) => s.q[usize::from(i)].cos(),
            Var::Qd(i) => s.qd[usize::from(i)],
            Var::Qdd(i) => s.qdd[usize::from(i)],
            _ => f64::NAN,
        });
        let mut tau = numeric.inverse_dynamics(&s.q, &s.qd, &s.qdd);
        // The spring of joint 2, known, not identified.
        tau[1] -= 12.0 * (s.q[1] - 0.2);
        for (i, t) in tau.iter().enumerate() {
            let predicted: f64 = (0..base.parameters.len())
                .map(|b| {
                    assert_eq!(estimates[b]["name"], base.parameters[b].name.as_str());
                    let x = estimates[b]["estimate"].as_f64().expect("a number");
                    values[base.regressor[i][b].index()] * x
                })
                .sum();
            worst = worst.max((predicted - t).abs());
            largest = largest.max(t.abs());
        }
    }
    assert!(worst < 1e-9 * largest, "{worst} of {largest}");
}

/// Noise-free data of a physical robot: the plain estimate is the description's base
/// parameters, which consistent parameters (the description's) have, so the consistent
/// estimate is the same, and every J_i ⪰ 0.
#[test]
fn a_consistent_plain_estimate_is_kept() {
    let states = fourier(4, 2000, 100.0, 1.3, &[]);
    let tau = torques(&arm(), &states, |_| 0.0);
    let csv = write_csv("consistent_exact.csv", &states, &tau, true);
    let mut args = vec![
        "identify",
        arm_file_static(),
        "--csv",
        &csv,
        "--json",
        "--consistent",
    ];
    let written = scratch("arm4_consistent.toml")
        .to_string_lossy()
        .into_owned();
    args.extend(ALL_TERMS);
    args.extend(["--description-out", &written]);
    let report = json(&dynamics(&args));
    check_written(&arm(), &written, &report);
    let plain = numbers(&report["parameters"], "estimate");
    let consistent = &report["consistent"];
    assert_eq!(consistent["plain_is_consistent"], true, "{consistent}");
    let base = numbers(&consistent["parameters"], "estimate");
    assert_eq!(plain.len(), base.len());
    for (p, c) in plain.iter().zip(&base) {
        assert!((p - c).abs() <= 1e-6 * p.abs().max(1e-3), "{p} {c}");
    }
    assert!(smallest_eigenvalues(&report).iter().all(|&e| e >= -1e-9));
    // The masses the torques determine: link 4's (a prismatic link's mass is in its own
    // equation's gravity and inertia terms) to 10⁻⁶.
    let mass = consistent["links"][3]["mass"].as_f64().unwrap();
    assert!((mass - 1.2).abs() < 1e-6, "{mass}");
}

/// A link of 20 g behind three heavy ones, two seconds of motion and torque noise of
/// 0.3 N m: the plain estimate's base parameters are those of no mass distribution; the
/// consistent one's are, and fit the torques nearly as well.
#[test]
fn an_inconsistent_plain_estimate_is_made_consistent() {
    let light = arm_text().replace("mass = 1.2", "mass = 0.02").replace(
        "inertia = [0.004, 0.005, 0.003, 0, 0, 0]",
        "inertia = [2e-5, 2e-5, 1e-5, 0, 0, 0]",
    );
    let path = scratch("light.toml");
    std::fs::write(&path, &light).expect("write robot");
    let robot = dynamics_codegen::front::load("light.toml", &light)
        .expect("reads")
        .robot;
    let states = fourier(4, 200, 100.0, 0.9, &[]);
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let tau = torques(&robot, &states, |_| 0.3 * normal(&mut seed));
    let csv = write_csv("consistent_noisy.csv", &states, &tau, true);
    let robot_file = path.to_string_lossy().into_owned();
    let mut args = vec![
        "identify",
        &robot_file,
        "--csv",
        &csv,
        "--json",
        "--consistent",
    ];
    let written = scratch("light_consistent.toml")
        .to_string_lossy()
        .into_owned();
    args.extend(ALL_TERMS);
    args.extend(["--description-out", &written]);
    let report = json(&dynamics(&args));
    check_written(&robot, &written, &report);
    let consistent = &report["consistent"];
    assert_eq!(consistent["plain_is_consistent"], false, "{consistent}");
    let eigenvalues = smallest_eigenvalues(&report);
    assert!(eigenvalues.iter().all(|&e| e >= -1e-9), "{eigenvalues:?}");
    let plain = numbers(&report["joints"], "residual_rms");
    let rms: Vec<f64> = consistent["residual_rms"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for (p, c) in plain.iter().zip(&rms) {
        assert!(*c <= 1.05 * p, "{plain:?} {rms:?}");
    }
    let (before, after) = (
        consistent["plain_weighted_residual"].as_f64().unwrap(),
        consistent["weighted_residual"].as_f64().unwrap(),
    );
    assert!(after > before && after < 1.05 * before, "{before} {after}");
}
