//! `dynamics identify --floating` on Solo 12, from measurements made by Pinocchio 4.1
//! (`tests/data/floating/make_identify.py`: `rnea` with the URDF's parameters along a smooth
//! motion given in closed form, v and a checked against differences along the configuration
//! space). The estimate must be the description's base parameters, the torques Pinocchio's; the
//! counts of identifiable parameters are the numerical ranks of Pinocchio's own regressor
//! stacked over the samples (the data's JSON), with every row and with the joints' alone.

use crate::synthetic::{dynamics, json, normal, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The repository's file at `path`.
fn repository(path: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    root.join(path).to_str().expect("UTF-8").to_string()
}

const SOLO12: &str = "robots/urdf/floating/solo12.urdf";
const DATA: &str = "tests/data/floating/solo12_identify.csv";

/// The data's JSON: the ranks of Pinocchio's stacked regressor.
fn ranks() -> (u64, u64) {
    let text = std::fs::read_to_string(repository("tests/data/floating/solo12_identify.json"));
    let data: Value = serde_json::from_str(&text.expect("the data")).expect("JSON");
    let rank = |key: &str| data[key].as_u64().expect("a rank");
    (rank("rank_all_rows"), rank("rank_joint_rows"))
}

/// The data's header and rows of numbers.
fn read_data() -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(repository(DATA)).expect("the data");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header = lines.next().expect("a header").split(',').map(String::from);
    let rows = lines.map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect());
    (header.collect(), rows.collect())
}

/// The columns `keep` (by name) of the data, written to the scratch file `name`.
fn write_columns(
    name: &str,
    header: &[String],
    rows: &[Vec<f64>],
    keep: impl Fn(&str) -> bool,
) -> String {
    let picked: Vec<usize> = (0..header.len()).filter(|&c| keep(&header[c])).collect();
    let mut text = picked
        .iter()
        .map(|&c| header[c].as_str())
        .collect::<Vec<_>>()
        .join(",")
        + "\n";
    for row in rows {
        let values: Vec<String> = picked.iter().map(|&c| format!("{:?}", row[c])).collect();
        text += &(values.join(",") + "\n");
    }
    let path = scratch(name);
    std::fs::write(&path, text).expect("scratch file");
    path.to_str().expect("UTF-8").to_string()
}

fn identify(csv: &str, extra: &[&str]) -> Value {
    let (robot, csv) = (repository(SOLO12), csv.to_string());
    let mut args = vec![
        "identify",
        robot.as_str(),
        "--floating",
        "--csv",
        csv.as_str(),
        "--json",
    ];
    args.extend(extra);
    json(&dynamics(&args))
}

/// Per parameter estimated: name, estimate, standard deviation, described value.
fn parameters(report: &Value) -> Vec<(String, f64, f64, f64)> {
    let list = report["parameters"].as_array().expect("parameters");
    let number = |p: &Value, k: &str| p[k].as_f64().expect("a number");
    list.iter()
        .map(|p| {
            let name = p["name"].as_str().expect("a name").to_string();
            (
                name,
                number(p, "estimate"),
                number(p, "std_dev"),
                number(p, "described"),
            )
        })
        .collect()
}

/// The largest |estimate − described|, each relative to the largest described value.
fn worst_error(report: &Value) -> f64 {
    let found = parameters(report);
    let scale = found.iter().fold(0.0f64, |m, p| m.max(p.3.abs()));
    found.iter().fold(0.0f64, |m, p| m.max((p.1 - p.3).abs())) / scale
}

#[test]
fn every_row_of_noise_free_data_gives_the_base_parameters_exactly() {
    let (rank_all, _) = ranks();
    let report = identify(&repository(DATA), &[]);
    assert_eq!(report["samples"].as_u64(), Some(1001));
    assert_eq!(report["derivatives"].as_str(), Some("v and a given"));
    assert!(report["rows"]
        .as_str()
        .expect("rows")
        .starts_with("all 18 of τ"));
    // 94 of the 130 standard parameters, as many as Pinocchio's regressor's rank.
    assert_eq!(parameters(&report).len() as u64, rank_all, "{report}");
    assert_eq!(report["unidentifiable"].as_array().map(Vec::len), Some(0));
    let error = worst_error(&report);
    assert!(error < 1e-9, "{error:e}");
    let rows = report["joints"].as_array().expect("rows");
    let labels: Vec<&str> = rows.iter().map(|r| r["row"].as_str().unwrap()).collect();
    assert_eq!(&labels[..7], ["fx", "fy", "fz", "mx", "my", "mz", "1"]);
    assert_eq!(rows[6]["tau"].as_u64(), Some(7));
    for row in rows {
        assert!(row["residual_rms"].as_f64().unwrap() < 1e-9, "{row}");
    }
}

/// `--consistent` on a floating base: `n + 1` bodies, the floating one first (its
/// pseudo-inertia about the base origin). On noise-free data of the description's bodies, which
/// are consistent, the consistent estimate is the plain one.
#[test]
fn the_consistent_estimate_of_noise_free_data_is_the_plain_one() {
    let report = identify(&repository(DATA), &["--consistent"]);
    let consistent = &report["consistent"];
    assert_eq!(consistent["plain_is_consistent"], true, "{consistent}");
    let links = consistent["links"].as_array().expect("links");
    assert_eq!(links.len(), 13);
    for link in links {
        assert!(
            link["smallest_eigenvalue"].as_f64().unwrap() >= -1e-9,
            "{link}"
        );
    }
    let plain = parameters(&report);
    let found = consistent["parameters"].as_array().expect("parameters");
    assert_eq!(found.len(), plain.len());
    let scale = plain.iter().fold(0.0f64, |m, p| m.max(p.1.abs()));
    for (p, c) in plain.iter().zip(found) {
        assert_eq!(c["name"].as_str(), Some(p.0.as_str()));
        let c = c["estimate"].as_f64().unwrap();
        assert!(
            (c - p.1).abs() <= 1e-6 * scale,
            "{}: {c} against {}",
            p.0,
            p.1
        );
    }
}

#[test]
fn the_joints_rows_alone_leave_the_floating_body_unidentified() {
    let (_, rank_joints) = ranks();
    let report = identify(&repository(DATA), &["--joint-rows"]);
    assert!(report["rows"]
        .as_str()
        .expect("rows")
        .starts_with("the joints' 12 of τ alone"));
    assert_eq!(parameters(&report).len() as u64, rank_joints, "{report}");
    // The floating body's ten, in the base's rows alone: zero columns in the joints'.
    // Its base parameters are the first ten of every row's fit (body by body from it).
    let named = report["unidentifiable"].as_array().expect("a list");
    assert_eq!(named.len(), 10, "{named:?}");
    let every = identify(&repository(DATA), &[]);
    let first_ten: Vec<String> = parameters(&every)[..10]
        .iter()
        .map(|p| p.0.clone())
        .collect();
    for (u, name) in named.iter().zip(&first_ten) {
        assert_eq!(u["name"].as_str(), Some(name.as_str()), "{u}");
        assert_eq!(u["combination"].as_array().map(Vec::len), Some(0), "{u}");
    }
    let error = worst_error(&report);
    assert!(error < 1e-9, "{error:e}");
    assert_eq!(report["joints"].as_array().map(Vec::len), Some(12));
    // The joints' torques alone in the file, tau7..tau18: the same fit.
    let (header, rows) = read_data();
    let joints_only = write_columns("solo12_joint_rows.csv", &header, &rows, |c| {
        !matches!(c, "tau1" | "tau2" | "tau3" | "tau4" | "tau5" | "tau6")
    });
    let again = identify(&joints_only, &["--joint-rows"]);
    assert_eq!(again["parameters"], report["parameters"]);
}

#[test]
fn noisy_torques_give_estimates_within_their_standard_deviations() {
    let (header, mut rows) = read_data();
    let first = header.iter().position(|c| c == "tau1").expect("tau1");
    // A different noise on each row: 0.5 N and 0.2 N m on the base's, 0.02 to 0.075 N m on the
    // joints'.
    let sigma: Vec<f64> = (0..18)
        .map(|i| match i {
            0..=2 => 0.5,
            3..=5 => 0.2,
            _ => 0.02 + 0.005 * (i - 6) as f64,
        })
        .collect();
    let mut seed = 0x5eed_2026_1130_u64;
    for row in &mut rows {
        for (i, s) in sigma.iter().enumerate() {
            row[first + i] += s * normal(&mut seed);
        }
    }
    let csv = write_columns("solo12_noisy.csv", &header, &rows, |_| true);
    let report = identify(&csv, &[]);
    let found = parameters(&report);
    let mut squared = 0.0;
    for (name, estimate, deviation, described) in &found {
        let z = (estimate - described) / deviation;
        assert!(
            z.abs() < 4.5,
            "{name}: {estimate} ± {deviation}, described {described}"
        );
        squared += z * z;
    }
    let mean = squared / found.len() as f64;
    assert!((0.5..1.6).contains(&mean), "{mean}");
    let reported = report["joints"].as_array().expect("rows");
    for (row, s) in reported.iter().zip(&sigma) {
        let estimated = row["sigma"].as_f64().unwrap();
        assert!((estimated / s - 1.0).abs() < 0.1, "{row}: {s}");
    }
}

#[test]
fn positions_alone_give_v_and_a_along_the_configuration_space() {
    let (header, rows) = read_data();
    let positions = write_columns("solo12_positions.csv", &header, &rows, |c| {
        !c.starts_with('v') && !c.starts_with('a')
    });
    let report = identify(&positions, &[]);
    assert_eq!(
        report["derivatives"].as_str(),
        Some("v and a by central differences along the configuration space")
    );
    let (rank_all, _) = ranks();
    assert_eq!(parameters(&report).len() as u64, rank_all);
    // Estimated from differences, so to their accuracy: (ω h)² / 12 of the accelerations
    // inside, first order in h at the two ends (as the fixed base's test).
    let scale = rows
        .iter()
        .flat_map(|r| &r[r.len() - 18..])
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for row in report["joints"].as_array().expect("rows") {
        assert!(
            row["residual_rms"].as_f64().unwrap() < 1e-3 * scale,
            "{row}"
        );
    }
    let error = worst_error(&report);
    assert!(error < 1e-4, "{error:e}");
}

/// Through the filters (the quaternion made continuous, filtered entry by entry and put back on
/// the unit sphere; τ and the regressor's columns alike, decimated), noise-free data still fit,
/// given v and a or from the positions alone.
#[test]
fn through_the_filters_noise_free_data_still_fit() {
    let (header, rows) = read_data();
    let scale = rows
        .iter()
        .flat_map(|r| &r[r.len() - 18..])
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let positions = write_columns("solo12_positions_filtered.csv", &header, &rows, |c| {
        !c.starts_with('v') && !c.starts_with('a')
    });
    for (csv, fit, estimates) in [(repository(DATA), 1e-6, 1e-6), (positions, 1e-4, 1e-4)] {
        let report = identify(&csv, &["--cutoff", "40"]);
        // ⌊0.4 · 500 / 40⌋: one sample in 5 of those whose window of 81 is full (the base's
        // rows have 92 parameters each: more samples than 20 Hz would keep).
        assert_eq!(report["filter"]["decimation"].as_u64(), Some(5));
        assert_eq!(report["samples"].as_u64(), Some(185));
        let residual = report["joints"].as_array().expect("rows").iter();
        let residual = residual.fold(0.0f64, |m, r| m.max(r["residual_rms"].as_f64().unwrap()));
        let error = worst_error(&report);
        assert!(residual < fit * scale, "{residual:e}");
        assert!(error < estimates, "{error:e}");
    }
}

/// The command's error on `text` as the CSV (with `extra` options): its exit code and stderr.
fn failure(name: &str, text: &str, extra: &[&str]) -> (Option<i32>, String) {
    let path: PathBuf = scratch(name);
    std::fs::write(&path, text).expect("scratch file");
    let robot = repository(SOLO12);
    let mut args = vec![
        "identify",
        robot.as_str(),
        "--floating",
        "--csv",
        path.to_str().unwrap(),
    ];
    args.extend(extra);
    let out = dynamics(&args);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bad_floating_samples_are_errors_at_their_line_and_column() {
    let (header, rows) = read_data();
    let line = |row: &[f64]| {
        row.iter()
            .map(|x| format!("{x:?}"))
            .collect::<Vec<_>>()
            .join(",")
    };
    let good = format!(
        "{}\n{}\n{}\n",
        header.join(","),
        line(&rows[0]),
        line(&rows[1])
    );
    // q of 18 values (a fixed base's count plus 6): the header's count is named.
    let short_q: Vec<&str> = header
        .iter()
        .map(String::as_str)
        .filter(|c| *c != "q19")
        .collect();
    let mut not_unit = rows[1].clone();
    not_unit[7] *= 1.01;
    let cases = [
        (
            format!("{}\n", short_q.join(",")),
            "line 1: the header has 73 columns; the robot has 12 joints on a floating base",
        ),
        (
            format!(
                "{}\n{}\n{}\n",
                header.join(","),
                line(&rows[0]),
                line(&not_unit)
            ),
            "line 3, column 5 (q4): the base's orientation q4..q7",
        ),
        (
            format!("{}\n{}\n", header.join(","), line(&rows[0][..40])),
            "line 2, column 41 (a3): 40 values; the header has 74 columns",
        ),
    ];
    for (k, (text, message)) in cases.iter().enumerate() {
        let (code, stderr) = failure(&format!("bad_floating{k}.csv"), text, &[]);
        assert_eq!(code, Some(1), "{stderr}");
        assert!(stderr.contains(message), "{message}: {stderr}");
    }
    // Read whole before the filter: the quaternion is checked as it is read.
    let (code, stderr) = failure(
        "bad_floating_filtered.csv",
        &cases[1].0,
        &["--cutoff", "20"],
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains(cases[1].1), "{stderr}");
    // Not supported on a floating base yet: usage errors that say so, never a panic.
    for (option, message) in [
        (
            &["--consistent", "--description-out", "out.toml"][..],
            "--description-out: a description's `[floating]` body is not rewritten yet",
        ),
        (
            &["--rotors"][..],
            "--rotors: the floating base's regressor has no joint columns",
        ),
    ] {
        let (code, stderr) = failure("good_floating.csv", &good, option);
        assert_eq!(code, Some(2), "{stderr}");
        assert!(
            stderr.contains(message) && !stderr.contains("panicked"),
            "{stderr}"
        );
    }
}
