//! The `dynamics` command end to end: `eval --json` against Pinocchio's reference data, errors
//! in description files reported as `file:line:col`, usage errors and help (clap's), `--`,
//! numbers without a negative zero, `stats` and `inspect`.
//! (`emit` is checked by the golden test and compiled by the `emitted_puma560` example;
//! `emit --lang c` by `c_header.rs`.)

use crate::runner::{dynamics, dynamics_in, root};
use dynamics_reference::scaled_error;
use dynamics_test_support::Scratch;
use serde_json::Value;
use std::process::Output;

fn stdout(out: &Output) -> String {
    assert!(
        out.status.success(),
        "failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).expect("UTF-8")
}

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        Value::Number(n) => vec![n.as_f64().expect("f64")],
        _ => panic!("not a number or an array: {v}"),
    }
}

/// `1.5,-2,...` with every digit of each number (Rust's shortest round-trip form).
fn list(v: &Value) -> String {
    let s: Vec<String> = numbers(v).iter().map(|x| format!("{x:?}")).collect();
    s.join(",")
}

/// `eval --json` on `description` reproduces τ, M, C and g of every sample of `data`; the worst
/// scaled error.
fn eval_matches(description: &str, data: &str) -> f64 {
    let data: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join(data)).expect("reference data"))
            .expect("json");
    let samples = data["samples"].as_array().expect("samples");
    assert_eq!(samples.len(), 20);
    let mut worst: f64 = 0.0;
    for s in samples {
        let out = dynamics(&[
            "eval",
            description,
            "--q",
            &list(&s["q"]),
            "--qd",
            &list(&s["qd"]),
            "--qdd",
            &list(&s["qdd"]),
            "--json",
        ]);
        let got: Value = serde_json::from_str(&stdout(&out)).expect("eval --json prints JSON");
        for (ours, theirs) in [("tau", "tau"), ("M", "M"), ("C", "C"), ("g", "g")] {
            let (a, b) = (numbers(&got[ours]), numbers(&s[theirs]));
            assert_eq!(a.len(), b.len(), "{description} {ours}: wrong size");
            let e = scaled_error(&a, &b);
            assert!(
                e < 1e-10,
                "{description} {ours} differs from Pinocchio by {e:e}"
            );
            worst = worst.max(e);
        }
    }
    println!("eval --json {description} vs reference: worst scaled error {worst:.1e}");
    worst
}

/// `eval --json` on `robots/puma560.toml` reproduces τ, M, C and g of every sample of
/// `tests/data/reference/data/puma560.json` (Pinocchio 4.1.0, a copy of the shared reference
/// data; see its README).
#[test]
fn eval_json_matches_the_reference_data() {
    eval_matches(
        "robots/puma560.toml",
        "tests/data/reference/data/puma560.json",
    );
}

/// The same for the 7-joint `robots/panda.toml` against `tests/data/panda/data.json`
/// (Pinocchio 4.1.0, made by `tests/data/panda/make.py`).
#[test]
fn eval_json_matches_the_panda_data() {
    eval_matches("robots/panda.toml", "tests/data/panda/data.json");
}

/// Parameters given with `--set`; a missing or unknown one is a usage error (exit code 2).
#[test]
fn eval_with_parameters() {
    let base = [
        "eval",
        "robots/niku_example_6_1.toml",
        "--q",
        "0.5",
        "--qdd",
        "2",
    ];
    let mut args = base.to_vec();
    args.extend(["--set", "m=3", "--set", "k=10", "--set", "g=9.81", "--json"]);
    let out = dynamics(&args);
    let got: Value = serde_json::from_str(&stdout(&out)).expect("JSON");
    // Example 6.1: F = m ẍ + k x = 3·2 + 10·0.5
    assert!((numbers(&got["tau"])[0] - 11.0).abs() < 1e-12, "{got}");
    assert!((numbers(&got["M"])[0] - 3.0).abs() < 1e-12, "{got}");

    let out = dynamics(&base);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("give --set"), "{err}");

    let mut args = base.to_vec();
    args.extend([
        "--set", "m=3", "--set", "k=1", "--set", "g=1", "--set", "z=1",
    ]);
    let out = dynamics(&args);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no parameter `z`"));

    let out = dynamics(&["eval", "robots/puma560.toml", "--q", "1,2"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("2 values given, the robot has 6 joints"));
}

/// Writes `text` to a fresh file named `name` and runs `dynamics inspect` on it; returns the
/// path as given and the error output (the run must fail with exit code 1).
fn inspect_bad_file(name: &str, text: &str) -> (String, String) {
    let dir = Scratch::new("cli");
    let path = dir.write(name, text).to_string_lossy().into_owned();
    let out = dynamics(&["inspect", &path]);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{name}: {}",
        String::from_utf8_lossy(&out.stdout)
    );
    (path, String::from_utf8(out.stderr).expect("UTF-8"))
}

/// Each error names the file, the line and the column of the offending value (1-based),
/// located here by searching the text for it.
#[test]
fn file_errors_have_line_and_column() {
    // (file name, text, the offending text, what the message says)
    let cases = [
        (
            "bad_value.toml",
            "name = \"arm\"\ngravity = [0, \"-g\", 0]\n\n[[joints]]\ntype = \"revolute\"\na = \"l1 +\"\nmass = \"m1\"\n",
            "\"l1 +\"",
            "cannot read `l1 +`",
        ),
        (
            "unknown_key.toml",
            "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\nmasss = 1\n",
            "masss",
            "unknown field `masss`",
        ),
        (
            "syntax.toml",
            "name = \"arm\"\ngravity = [0, 0, -9.81\n",
            "\n",
            "",
        ),
        (
            "joint_kind.json",
            "{\"name\": \"arm\", \"gravity\": [0, 0, -9.81],\n \"joints\": [\n  {\"type\": \"sliding\", \"mass\": 1}\n ]}\n",
            "\"sliding\"",
            "unknown variant `sliding`",
        ),
        (
            "negative_mass.json",
            "{\"name\": \"arm\", \"gravity\": [0, 0, -9.81],\n \"joints\": [\n  {\"type\": \"revolute\",\n   \"mass\": -2}\n ]}\n",
            "-2",
            "joint 1: the mass is negative",
        ),
        (
            "bad_inertia.toml",
            "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\nmass = 1\ninertia = [0, 0.35, 0, 0, 0, 0]\n",
            "[0, 0.35",
            "joint 1: the principal moments of inertia",
        ),
    ];
    for (name, text, at, says) in cases {
        let (path, err) = inspect_bad_file(name, text);
        let message = err
            .strip_prefix("dynamics: ")
            .unwrap_or_else(|| panic!("{name}: {err}"));
        let rest = message
            .strip_prefix(&format!("{path}:"))
            .unwrap_or_else(|| panic!("{name}: no file name in {err}"));
        let mut parts = rest.splitn(3, ':');
        let line: usize = parts.next().and_then(|l| l.parse().ok()).expect(&err);
        let col: usize = parts.next().and_then(|c| c.parse().ok()).expect(&err);
        assert!(
            parts.next().expect(&err).contains(says),
            "{name}: message: {err}"
        );
        if name == "syntax.toml" {
            // an unclosed array: reported on its line, after what was read
            assert_eq!(line, 2, "{err}");
            assert!(col > "gravity = [".len(), "{err}");
            continue;
        }
        let offset = text.find(at).expect("offending text");
        let want_line = text[..offset].matches('\n').count() + 1;
        let want_col = offset - text[..offset].rfind('\n').map_or(0, |n| n + 1) + 1;
        // The TOML parser points at the key or the value, the JSON parser at the end of the
        // value: the same line, between the key and the end of the value.
        assert_eq!(line, want_line, "{name}: {err}");
        let line_start = text[..offset].rfind('\n').map_or(0, |n| n + 1);
        let key_col = text[line_start..]
            .find(|c: char| !c.is_whitespace())
            .map_or(1, |n| n + 1);
        let end_col = want_col + at.chars().count();
        assert!(
            (key_col..=end_col).contains(&col),
            "{name}: column {col}, want {key_col}..={end_col}: {err}"
        );
    }
}

/// `check_inertia = false` keeps a published tensor that fails the check (principal moments
/// 0 + 0 < 0.35), as the derive does; about z0 = z1 the link's inertia is Izz.
#[test]
fn check_inertia_opt_out() {
    let dir = Scratch::new("cli-opt-out");
    let path = dir.write(
        "opt_out.toml",
        "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
         inertia = [0, 0, 0.35, 0, 0, 0]\ncheck_inertia = false\n",
    );
    let out = stdout(&dynamics(&["inspect", &path.to_string_lossy()]));
    assert!(out.contains("D11 = 0.35"), "{out}");
}

/// Usage errors are clap's: exit code 2, the message on stderr, nothing on stdout. A missing file is not a usage error (exit code 1).
#[test]
fn usage_errors() {
    for (args, says) in [
        (vec![], "Usage: dynamics <COMMAND>"),
        (
            vec!["frobnicate", "robots/puma560.toml"],
            "unrecognized subcommand 'frobnicate'",
        ),
        (vec!["inspect"], "required arguments were not provided"),
        (
            vec!["inspect", "robots/puma560.toml", "--tex"],
            "unexpected argument '--tex'",
        ),
        (vec!["eval", "robots/puma560.toml"], "--q <Q1,Q2,..>"),
        (
            vec!["eval", "robots/puma560.toml", "--q", "0,x,0"],
            "`x` is not a finite number",
        ),
        (
            vec!["eval", "robots/puma560.toml", "--q", "0", "--q", "1"],
            "cannot be used multiple times",
        ),
        (
            vec![
                "eval",
                "robots/niku_example_6_1.toml",
                "--q",
                "0",
                "--set",
                "m",
            ],
            "expected NAME=VALUE",
        ),
        (
            vec!["emit", "robots/puma560.toml", "--lang", "fortran"],
            "[possible values: rust, c]",
        ),
    ] {
        let out = dynamics(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
        // clap's ending (or, with no command at all, its help)
        assert!(err.contains("--help"), "{args:?}: {err}");
    }
    let out = dynamics(&["inspect", "robots/nowhere.toml"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("robots/nowhere.toml: "));
}

/// `COMMAND --help` prints, on stdout with exit code 0, the command's one-line about, its usage
/// and every option; `help COMMAND` prints the same.
#[test]
fn help_of_each_command() {
    for (command, about, options) in [
        (
            "inspect",
            "the equations of motion",
            &["<ROBOT>", "--latex"][..],
        ),
        ("emit", "a standalone Rust module", &["<ROBOT>"][..]),
        ("stats", "operation counts", &["<ROBOT>", "--runs <N>"][..]),
        (
            "eval",
            "τ, M, C and g at one state",
            &[
                "<ROBOT>",
                "--q <",
                "--qd <",
                "--qdd <",
                "--set <NAME=VALUE>",
                "--json",
            ][..],
        ),
    ] {
        let help = stdout(&dynamics(&[command, "--help"]));
        let first = help.lines().next().unwrap_or_default();
        assert!(first.contains(about), "{command}: {help}");
        assert!(
            help.contains(&format!("Usage: dynamics {command} ")),
            "{command}: {help}"
        );
        for option in options {
            assert!(help.contains(option), "{command}: no {option} in {help}");
        }
        assert_eq!(stdout(&dynamics(&["help", command])), help);
    }
    let help = stdout(&dynamics(&["--help"]));
    for command in ["inspect", "emit", "stats", "eval"] {
        assert!(help.contains(&format!("  {command}  ")), "{help}");
    }
}

#[test]
fn version() {
    let out = stdout(&dynamics(&["--version"]));
    assert_eq!(out, format!("dynamics {}\n", env!("CARGO_PKG_VERSION")));
}

/// After `--` an argument that looks like an option is the ROBOT file; before it, it is an
/// unknown option.
#[test]
fn double_dash_ends_the_options() {
    let scratch = Scratch::new("cli-dash");
    // One link of length 2 with a point mass 3 at its end, turning in the plane of gravity.
    let _ = scratch.write(
        "-x.json",
        r#"{"name": "arm", "gravity": [0, -9.81, 0], "joints": [{"type": "revolute", "a": 2, "mass": 3}]}"#,
    );
    let dir = scratch.path();
    let out = dynamics_in(dir, &["eval", "--q", "0", "--json", "--", "-x.json"]);
    let got: Value = serde_json::from_str(&stdout(&out)).expect("JSON");
    // Held horizontal: τ = m g a = 3 · 9.81 · 2; M = m a² = 12.
    assert!((numbers(&got["tau"])[0] - 58.86).abs() < 1e-12, "{got}");
    assert!((numbers(&got["M"])[0] - 12.0).abs() < 1e-12, "{got}");

    // Read as the short option `-x`.
    let out = dynamics_in(dir, &["inspect", "-x.json"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("unexpected argument '-x'"), "{err}");
}

/// At rest (q̇ = 0) the Coriolis matrix, linear in q̇, is exactly zero: every entry prints as
/// an unsigned zero, in text and in JSON, as does every other zero (PUMA 560 at q = 0 has
/// entries that come out as -0.0 in floating point).
#[test]
fn zeros_print_without_sign() {
    let args = ["eval", "robots/puma560.toml", "--q", "0,0,0,0,0,0"];
    let text = stdout(&dynamics(&args));
    assert!(!text.contains("-0.000000e0"), "{text}");
    let c: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("C ="))
        .skip(1)
        .take(6)
        .collect();
    for row in &c {
        let entries: Vec<&str> = row
            .trim()
            .trim_matches(['[', ']'])
            .split_whitespace()
            .collect();
        assert_eq!(entries, ["0.000000e0"; 6], "{text}");
    }

    let json = stdout(&dynamics(&[&args[..], &["--json"]].concat()));
    let tokens: Vec<&str> = json
        .split(|c: char| !(c.is_ascii_digit() || "-.eE".contains(c)))
        .collect();
    assert!(!tokens.contains(&"-0.0"), "{json}");
    let got: Value = serde_json::from_str(&json).expect("JSON");
    assert_eq!(numbers(&got["C"]), [0.0; 36]);
    for x in ["tau", "M", "C", "g"]
        .iter()
        .flat_map(|k| numbers(&got[*k]))
    {
        assert!(x != 0.0 || x.is_sign_positive(), "{json}");
    }
}

/// `stats` lists the sixteen methods with their operation counts; the shared code's and the
/// per-method code sizes add up to the total.
#[test]
fn stats_per_method() {
    let out = stdout(&dynamics(&["stats", "robots/puma560.toml"]));
    let mut total = 0;
    let mut methods = Vec::new();
    for line in out.lines().skip(2) {
        let cols: Vec<&str> = line.split_whitespace().collect();
        // `(configuration)`, `(motion)` and the kinematic methods' `(kinematic …)`.
        if line.starts_with('(') {
            // The shared code: computed once, its operations counted in the methods that
            // read it.
            total += cols
                .last()
                .and_then(|b| b.parse::<usize>().ok())
                .expect("bytes");
            continue;
        }
        if line.starts_with("total generated code") {
            let t: usize = cols[3].parse().expect("total");
            assert_eq!(t, total, "{out}");
            break;
        }
        assert_eq!(cols.len(), 9, "{line}");
        let n: Vec<usize> = cols[1..]
            .iter()
            .map(|c| c.parse().expect("count"))
            .collect();
        // flops = mul + add + neg + div
        assert_eq!(n[5], n[0] + n[1] + n[2] + n[3], "{line}");
        // the longest chain is at most all of them
        assert!(n[6] <= n[5], "{line}");
        total += n[7];
        methods.push(cols[0].to_string());
    }
    assert_eq!(
        methods,
        [
            "mass_matrix",
            "coriolis_matrix",
            "coriolis_torques",
            "gravity_torques",
            "bias_torques",
            "inverse_dynamics",
            "kinetic_energy",
            "potential_energy",
            "hand_pose",
            "link_poses",
            "hand_jacobian_in_base",
            "hand_jacobian_in_hand",
            "hand_acceleration_bias_in_base",
            "hand_acceleration_bias_in_hand",
            "joint_torques_for_hand_wrench",
            "joint_torques_for_base_wrench",
            "mass_matrix_inverse",
            "forward_dynamics"
        ]
    );
}

/// The simplified models need an envelope and tolerances: `--with simplify` is a usage error
/// that says where they go, not an emission without them.
#[test]
fn with_simplify_is_refused() {
    let out = dynamics(&["emit", "robots/puma560.toml", "--with", "simplify"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--simplified --tolerance"), "{err}");
}
