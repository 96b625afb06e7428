//! `dynamics excite` end to end: the trajectory file read back and checked sample by sample
//! against the limits and against its own differences; its condition number recomputed from
//! the base regressor's graph (`Graph::eval`, not the tape the command uses) and nalgebra's SVD;
//! the file identified by `dynamics identify` once torques from the numeric inverse dynamics are
//! appended; the same seed, the same file.

use crate::runner::dynamics;
use dynamics_codegen::derive;
use dynamics_codegen::numeric::Numeric;
use dynamics_codegen::symbolic::Var;
use serde_json::Value;
use std::path::PathBuf;

const PUMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");
const PANDA_URDF: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf/panda.urdf");

fn scratch(name: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_excite");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name).to_string_lossy().into_owned()
}

/// Runs `excite` with `args`, the trajectory to `name`: the JSON report and the file's rows.
fn excite(name: &str, args: &[&str]) -> (Value, Vec<Vec<f64>>) {
    let csv = scratch(name);
    let mut all = vec!["excite"];
    all.extend(args);
    all.extend(["--csv", &csv, "--json"]);
    let out = dynamics(&all);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let report = serde_json::from_slice(&out.stdout).expect("JSON");
    (report, read(&csv))
}

/// The rows of a trajectory file, its header checked.
fn read(path: &str) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path).expect("the trajectory");
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    let n = (header.split(',').count() - 1) / 3;
    let mut want = vec!["t".to_string()];
    for group in ["q", "qd", "qdd"] {
        want.extend((1..=n).map(|i| format!("{group}{i}")));
    }
    assert_eq!(header, want.join(","));
    lines
        .map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect())
        .collect()
}

/// The limits of joint j in a report: lower, upper, speed, acceleration.
fn limits(report: &Value, j: usize) -> [f64; 4] {
    let l = &report["joints"][j]["limits"];
    ["lower", "upper", "velocity", "acceleration"].map(|k| l[k].as_f64().expect("a number"))
}

#[test]
fn the_limits_hold_at_every_sample_and_the_derivatives_are_the_series() {
    let args = [
        PUMA,
        "--q-min",
        "-1,-2,-0.5,-1,-1,-3",
        "--q-max",
        "1,0.5,1.5,1,1,3",
        "--qd-max",
        "0.8",
        "--qdd-max",
        "2,3,4,5,6,7",
        "--periods",
        "2",
        "--rate",
        "200",
        "--evaluations",
        "40",
    ];
    let (report, rows) = excite("limits.csv", &args);
    let n = 6;
    // Two periods of 10 s at 200 Hz, and the first sample of the next.
    assert_eq!(rows.len(), 4001);
    assert_eq!(rows[4000][0], 20.0);
    let h = 1.0 / 200.0;
    for j in 0..n {
        let [lower, upper, speed, acceleration] = limits(&report, j);
        assert_eq!(report["joints"][j]["limits_from"]["lower"], "option");
        let mut reached = [f64::MAX, f64::MIN, 0.0f64, 0.0f64];
        for (k, row) in rows.iter().enumerate() {
            let (q, qd, qdd) = (row[1 + j], row[1 + n + j], row[1 + 2 * n + j]);
            assert!(q >= lower && q <= upper, "joint {} row {k}: {q}", j + 1);
            assert!(qd.abs() <= speed && qdd.abs() <= acceleration, "{j} {k}");
            reached = [
                reached[0].min(q),
                reached[1].max(q),
                reached[2].max(qd.abs()),
                reached[3].max(qdd.abs()),
            ];
            // Central differences of q and q̇: the series' derivatives, to O(h²).
            if k > 0 && k < rows.len() - 1 {
                let (before, after) = (&rows[k - 1], &rows[k + 1]);
                let dq = (after[1 + j] - before[1 + j]) / (2.0 * h);
                let dqd = (after[1 + n + j] - before[1 + n + j]) / (2.0 * h);
                assert!((dq - qd).abs() < 1e-3 * speed, "{j} {k}: {dq} {qd}");
                assert!((dqd - qdd).abs() < 1e-3 * acceleration, "{j} {k}");
            }
        }
        // One of the four limits binds: the motion is as large as they allow.
        let ratios = [
            (reached[1] - reached[0]) / (upper - lower),
            reached[2] / speed,
            reached[3] / acceleration,
        ];
        assert!(ratios.iter().any(|r| *r > 1.0 - 1e-6), "{j}: {ratios:?}");
        // At rest at the start of each period, where the rows repeat the first.
        for k in [0, 2000, 4000] {
            assert_eq!(rows[k][1 + n + j], 0.0);
            assert_eq!(rows[k][1 + 2 * n + j], 0.0);
            assert_eq!(rows[k][1 + j], rows[0][1 + j]);
        }
        // serde_json's default float parsing may be one ulp off.
        let start = report["start"][j].as_f64().expect("a number");
        assert!((start - rows[0][1 + j]).abs() < 1e-15, "{start}");
    }
}

/// `σ_max / σ_min` of the stacked base regressor of the first period's rows, the regressor's
/// graph evaluated whole and the SVD nalgebra's.
fn condition_number(robot: &str, rows: &[Vec<f64>], samples: usize) -> f64 {
    let text = std::fs::read_to_string(robot).expect("robot");
    let robot = dynamics_codegen::front::load(robot, &text)
        .expect("reads")
        .robot;
    let mut eq = derive(&robot);
    let none = dynamics_codegen::trace::base_parameters::JointColumns::default();
    let base = eq
        .base_parameters(&robot, &vec![none; eq.dof])
        .expect("numbers only");
    let (n, b) = (eq.dof, base.parameters.len());
    let mut stacked = nalgebra::DMatrix::zeros(samples * n, b);
    for (k, row) in rows[..samples].iter().enumerate() {
        let values = eq.graph.eval(|v| match v {
            Var::Q(i) => row[1 + usize::from(i)],
            Var::SinQ(i) => row[1 + usize::from(i)].sin(),
            Var::CosQ(i) => row[1 + usize::from(i)].cos(),
            Var::Qd(i) => row[1 + n + usize::from(i)],
            Var::Qdd(i) => row[1 + 2 * n + usize::from(i)],
            _ => f64::NAN,
        });
        for i in 0..n {
            for c in 0..b {
                stacked[(k * n + i, c)] = values[base.regressor[i][c].index()];
            }
        }
    }
    let singular = stacked.singular_values();
    singular.max() / singular.min()
}

#[test]
fn the_condition_number_is_the_stacked_regressor_s_and_lower_than_the_first_guess_s() {
    let (report, rows) = excite("condition.csv", &[PUMA, "--evaluations", "60"]);
    let found = report["condition_number"].as_f64().expect("a number");
    let initial = report["initial_condition_number"]
        .as_f64()
        .expect("a number");
    assert!(found < initial, "{found} {initial}");
    assert_eq!(report["samples_per_period"].as_u64(), Some(1000));
    assert_eq!(report["base_parameters"].as_u64(), Some(36));
    let independent = condition_number(PUMA, &rows, 1000);
    assert!(
        (found - independent).abs() < 1e-8 * independent,
        "{found} {independent}"
    );
}

#[test]
fn identify_reads_the_trajectory_with_torques_appended_and_recovers_every_parameter() {
    let (_, rows) = excite(
        "identify.csv",
        &[PUMA, "--evaluations", "30", "--seed", "4"],
    );
    // `size` reads the trajectory as written.
    let trajectory = scratch("identify.csv");
    assert!(dynamics(&["size", PUMA, "--csv", &trajectory, "--json"])
        .status
        .success());
    let text = std::fs::read_to_string(PUMA).expect("robot");
    let robot = dynamics_codegen::front::load(PUMA, &text)
        .expect("reads")
        .robot;
    let numeric = Numeric::new(&robot, &[]).expect("no fields");
    let n = 6;
    let original = std::fs::read_to_string(&trajectory).expect("trajectory");
    let mut lines = original.lines();
    let taus: Vec<String> = (1..=n).map(|i| format!("tau{i}")).collect();
    let mut measured = format!("{},{}\n", lines.next().expect("header"), taus.join(","));
    for (line, row) in lines.zip(&rows) {
        let (q, qd, qdd) = (&row[1..=n], &row[1 + n..=2 * n], &row[1 + 2 * n..]);
        let tau: Vec<String> = numeric
            .inverse_dynamics(q, qd, qdd)
            .iter()
            .map(f64::to_string)
            .collect();
        measured += &format!("{line},{}\n", tau.join(","));
    }
    let csv = scratch("measured.csv");
    std::fs::write(&csv, measured).expect("write");
    let out = dynamics(&["identify", PUMA, "--csv", &csv, "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(report["unidentifiable"].as_array().map(Vec::len), Some(0));
    let parameters = report["parameters"].as_array().expect("parameters");
    assert_eq!(parameters.len(), 36);
    let largest = parameters
        .iter()
        .map(|p| p["described"].as_f64().unwrap().abs())
        .fold(0.0, f64::max);
    for p in parameters {
        let (estimate, described) = (p["estimate"].as_f64(), p["described"].as_f64());
        let error = (estimate.unwrap() - described.unwrap()).abs();
        assert!(error < 1e-8 * largest, "{p}");
    }
}

#[test]
fn the_same_seed_writes_the_same_file() {
    let args = |seed: &'static str| [PUMA, "--evaluations", "25", "--seed", seed];
    excite("seed5.csv", &args("5"));
    excite("seed5_again.csv", &args("5"));
    excite("seed6.csv", &args("6"));
    let file = |name: &str| std::fs::read(scratch(name)).expect("written");
    assert_eq!(file("seed5.csv"), file("seed5_again.csv"));
    assert_ne!(file("seed5.csv"), file("seed6.csv"));
}

/// The Panda's URDF gives its ranges and speeds (Franka's published limits); the acceleration
/// is asked for.
#[test]
fn a_urdf_gives_its_limits() {
    let args = [
        PANDA_URDF,
        "--tip",
        "panda_hand",
        "--qdd-max",
        "3",
        "--evaluations",
        "10",
    ];
    let (report, rows) = excite("panda.csv", &args);
    let from = &report["joints"][3]["limits_from"];
    assert_eq!(
        [&from["lower"], &from["upper"], &from["velocity"]],
        ["URDF", "URDF", "URDF"]
    );
    assert_eq!(from["acceleration"], "option");
    assert_eq!(limits(&report, 3), [-3.0718, -0.0698, 2.175, 3.0]);
    assert_eq!(limits(&report, 6), [-2.8973, 2.8973, 2.61, 3.0]);
    for row in &rows {
        assert!(row[4] >= -3.0718 && row[4] <= -0.0698, "{row:?}");
    }
}

#[test]
fn bad_limits_and_samplings_are_usage_errors() {
    let cases: [(&[&str], &str); 5] = [
        (
            &["--q-min", "0,0"],
            "--q-min: 2 values; give one for every joint or one for each of the 6 joints",
        ),
        (
            &["--q-min", "1", "--q-max", "0.5"],
            "joint 1: the range [1, 0.5] is empty",
        ),
        (&["--qd-max", "0"], "--qd-max: joint 1: 0 is not positive"),
        (&["--rate", "2"], "--period × --rate: 20 samples per period"),
        // 10 s at 100 Hz: 1000 samples a period, 10⁷ lines of 19 numbers.
        (
            &["--periods", "10001"],
            "about 3.8 GB of output; a run takes at most 1.0 GB of output without --no-limits",
        ),
    ];
    for (extra, message) in cases {
        let mut args = vec!["excite", PUMA, "--evaluations", "1"];
        args.extend(extra);
        let out = dynamics(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {stderr}");
        assert!(stderr.contains(message), "{stderr}");
    }
    let out = dynamics(&["excite", PUMA, "--harmonics", "1"]);
    assert_eq!(out.status.code(), Some(2));
}
