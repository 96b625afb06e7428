//! Every option of every command, as clap declares them (`dynamics_cli::command()`: a new option
//! is tried without a change here), given the values a hurried or careless user gives: NaN, ±∞,
//! negative, zero, huge and tiny numbers, words, empty values and lists, lists one too long or
//! too short, the option twice. Each run must end within a timeout, by itself (no signal, no
//! panic), with exit code 0, 1 or 2; an error must name the option (or the file it names) and
//! say what it expected; a success must print no NaN.
//!
//! The runs are the binary's (a crash or an abort is one too), two at a time, on a 2-joint robot
//! whose equations derive in milliseconds.

use crate::fuzz;

use fuzz::{check, run_all, Case, Outcome};
use std::path::{Path, PathBuf};

/// The robot of every run but those of `--set`: two revolute joints with friction and a rotor.
const ROBOT: &str = "robots/two_link_friction.toml";
/// A robot with parameters (`g`, `l1`, `l2`, `m1`, `m2`) for `--set`.
const PARAMETERS: &str = "robots/niku_example_6_4.toml";
const JOINTS: usize = 2;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// The scratch directory the runs work in (files they write land there).
fn scratch() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_fuzz");
    // Emptied first: a file an earlier run wrote (`--csv NaN`) must not become the input of
    // this run's case in the same numbered folder (`--batch NaN`).
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// Values no option takes as they are, or only some do: each is tried on every option.
fn bad_values() -> Vec<String> {
    let long = ["0.5"; JOINTS + 1].join(",");
    let short = ["0.5"; JOINTS - 1].join(",");
    let mut values: Vec<String> = [
        "NaN",
        "inf",
        "-inf",
        "-1",
        "-0.5,0.5",
        "0",
        "1e308",
        "-1e308",
        "1e-300",
        "100000000",
        "18446744073709551616",
        "abc",
        "",
        ",",
        "1,,2",
        "/nonexistent/dir/file",
        ".",
    ]
    .map(String::from)
    .to_vec();
    values.extend([long, short]);
    values
}

/// A command's line that runs quickly and succeeds, on [`ROBOT`]; the measurements `identify`
/// reads are written first.
fn base(command: &str, dir: &Path) -> Vec<String> {
    let robot = root().join(ROBOT).display().to_string();
    let measured = dir.join("measured.csv").display().to_string();
    let rest: &[&str] = match command {
        "stats" => &["--runs", "1"],
        "eval" => &["--q", "0.1,0.2"],
        "size" => &["--from", "0,0", "--to", "1,1", "--samples", "11"],
        "simulate" => &["--duration", "0.01", "--csv", "simulated.csv"],
        "identify" => &["--csv", &measured],
        "excite" => &[
            "--evaluations",
            "10",
            "--period",
            "2",
            "--rate",
            "20",
            "--csv",
            "excited.csv",
        ],
        _ => &[],
    };
    std::iter::once(robot.as_str())
        .chain(rest.iter().copied())
        .map(String::from)
        .collect()
}

/// What an option needs beside the base line (the options it requires), and the base's options
/// it cannot stand with.
fn context(command: &str, option: &str) -> (&'static [&'static str], &'static [&'static str]) {
    let simplified = [
        "tolerance",
        "tolerance-percent",
        "rated",
        "q-min",
        "q-max",
        "qd-max",
        "qdd-max",
    ];
    match (command, option) {
        ("inspect" | "stats", "tolerance" | "tolerance-percent") => (&["--simplified"], &[]),
        ("inspect" | "stats", o) if simplified.contains(&o) => {
            (&["--simplified", "--tolerance", "1"], &[])
        }
        ("identify", "validate-plot") => (&["--validate", "measured.csv"], &[]),
        ("identify", "description-out") => (&["--consistent"], &[]),
        ("size", "csv") => (&[], &["--from", "--to"]),
        ("simulate", "batch") => (&[], &[]),
        _ => (&[], &[]),
    }
}

/// `words` without the options `remove` and their values, with `option value` in place of the
/// option's own (or added).
fn with_option(
    words: &[String],
    remove: &[&str],
    option: &str,
    value: Option<&str>,
) -> Vec<String> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < words.len() {
        let w = words[i].as_str();
        if w == option || remove.contains(&w) {
            i += 2;
            continue;
        }
        out.push(words[i].clone());
        i += 1;
    }
    out.push(option.to_string());
    out.extend(value.map(String::from));
    out
}

/// The cases of one command: every value of [`bad_values`] for each option that takes one, every
/// option twice, the robot file missing, empty or a directory.
fn cases(command: &clap::Command, dir: &Path) -> Vec<Case> {
    let name = command.get_name();
    let base = base(name, dir);
    let mut cases = Vec::new();
    for arg in command.get_arguments() {
        let id = arg.get_id().as_str();
        if ["help", "version"].contains(&id) {
            continue;
        }
        if arg.is_positional() {
            for value in [
                "",
                "/nonexistent/robot.toml",
                ".",
                "/dev/null",
                "Cargo.toml",
            ] {
                let mut words = base.clone();
                words[0] = value.to_string();
                cases.push(Case::new(name, "ROBOT", value, words));
            }
            continue;
        }
        let long = format!("--{}", arg.get_long().expect("options are long"));
        let (extra, remove) = context(name, arg.get_long().unwrap_or_default());
        let mut line = base.clone();
        let measured = dir.join("measured.csv").display().to_string();
        line.extend(extra.iter().map(|&w| match w {
            "measured.csv" => measured.clone(),
            w => w.to_string(),
        }));
        let takes_value = arg.get_num_args().is_some_and(|n| n.takes_values());
        if !takes_value {
            let mut twice = with_option(&line, remove, &long, None);
            twice.push(long.clone());
            cases.push(Case::new(name, &long, "(twice)", twice));
            continue;
        }
        for value in bad_values() {
            let words = with_option(&line, remove, &long, Some(&value));
            cases.push(Case::new(name, &long, &value, words));
        }
        let mut twice = with_option(&line, remove, &long, Some("1"));
        twice.extend([long.clone(), "1".to_string()]);
        cases.push(Case::new(name, &long, "1 (twice)", twice));
    }
    cases
}

/// `--set` on a robot with parameters, for the commands that take its values (those whose line
/// with good values succeeds): each bad value in place of one parameter's.
fn settings_cases(command: &clap::Command, dir: &Path) -> Vec<Case> {
    let name = command.get_name();
    if !command.get_arguments().any(|a| a.get_long() == Some("set")) {
        return Vec::new();
    }
    let robot = root().join(PARAMETERS).display().to_string();
    let mut base = base(name, dir);
    base[0] = robot;
    for set in ["g=9.81", "l1=1", "l2=0.5", "m2=1"] {
        base.extend(["--set".to_string(), set.to_string()]);
    }
    let with = |value: &str| {
        let mut words = base.clone();
        words.extend(["--set".to_string(), value.to_string()]);
        Case::new(name, "--set", value, words)
    };
    let good = with("m1=2");
    let probe = run_all(
        env!("CARGO_BIN_EXE_dynamics"),
        dir,
        std::slice::from_ref(&good),
    );
    if probe[0].code != Some(0) {
        return Vec::new();
    }
    let mut cases: Vec<Case> = bad_values()
        .iter()
        .map(|value| with(&format!("m1={value}")))
        .collect();
    cases.extend(["m1", "=1", "m1=1=2", "nope=1", "m1=1,m2=1"].map(with));
    let mut twice = base.clone();
    twice.extend(["--set", "m1=1", "--set", "m1=2"].map(String::from));
    cases.push(Case::new(name, "--set", "m1 (twice)", twice));
    cases
}

/// Measurements `identify` fits (their torques made up: the fit is not what is tested).
fn write_measurements(dir: &Path) {
    let mut text = String::from("t,q1,q2,qd1,qd2,qdd1,qdd2,tau1,tau2\n");
    for k in 0..200 {
        let t = f64::from(k) * 0.01;
        let (s, c) = (t.sin(), (1.7 * t).cos());
        let row = [t, s, c, t.cos(), -1.7 * (1.7 * t).sin(), -s, -2.89 * c];
        let tau = [2.0 * s + 0.3 * c + 0.1, -c + 0.5 * s];
        let values: Vec<String> = row.iter().chain(&tau).map(f64::to_string).collect();
        text += &(values.join(",") + "\n");
    }
    std::fs::write(dir.join("measured.csv"), text).expect("measurements");
}

#[test]
fn every_option_with_bad_values() {
    let dir = scratch();
    write_measurements(&dir);
    let mut cli = dynamics_cli::command();
    // Every argument's action and number of values, as parsing sees them.
    cli.build();
    let mut all = Vec::new();
    for command in cli.get_subcommands() {
        all.extend(cases(command, &dir));
        all.extend(settings_cases(command, &dir));
    }
    let outcomes = run_all(env!("CARGO_BIN_EXE_dynamics"), &dir, &all);
    let problems: Vec<String> = all
        .iter()
        .zip(&outcomes)
        .filter_map(|(case, outcome): (&Case, &Outcome)| check(case, outcome))
        .collect();
    let log: Vec<String> = all
        .iter()
        .zip(&outcomes)
        .map(|(case, outcome)| {
            format!(
                "{} {} {:?}: {}",
                case.command,
                case.option,
                case.value,
                outcome.summary()
            )
        })
        .collect();
    std::fs::write(dir.join("log.txt"), log.join("\n")).expect("log");
    assert!(
        problems.is_empty(),
        "{} of {} runs went wrong:\n{}",
        problems.len(),
        all.len(),
        problems.join("\n")
    );
}
