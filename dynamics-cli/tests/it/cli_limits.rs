//! Runs whose cost the options set: refused past their limits, up front, with what they would
//! cost and the option that allows them; numbers that make a result non-finite refused with the
//! options that gave them. In process (`dynamics_cli::run`): each refusal is immediate.

use dynamics_cli::run;
use std::path::PathBuf;

fn robot(name: &str) -> String {
    format!("{}/../robots/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_limits");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path.display().to_string()
}

/// The error of `words`, which must fail.
fn error(words: &[&str]) -> String {
    match run(words) {
        Ok(out) => panic!("{words:?} succeeded: {out}"),
        Err(e) => e,
    }
}

fn contains_all(text: &str, parts: &[&str]) {
    for part in parts {
        assert!(text.contains(part), "no `{part}` in\n{text}");
    }
}

/// Two states are one group of lanes, which costs what four do: 5·10⁸ steps of it (hours), where
/// the limit used to count 10⁹ state-steps and took it.
#[test]
fn a_batch_counts_steps_of_a_group_of_lanes() {
    let states = scratch("two_states.csv", "t,q1,q2\n0,0.1,0.2\n1,0.3,0.4\n");
    let e = error(&[
        "simulate",
        &robot("two_link_friction.toml"),
        "--batch",
        &states,
        "--duration",
        "500000",
        "--csv",
        &scratch("unwritten.csv", ""),
    ]);
    contains_all(
        &e,
        &[
            "--batch, --duration / --dt: 5e8 RK4 steps of a group (2 states in 1 group of up \
             to 4, 500000000 steps each), about ",
            "a run takes at most 1e6 RK4 steps of a group without --no-limits",
        ],
    );
}

/// One state at the old cap: 10⁷ steps, 3.5 GB of CSV for the PUMA.
#[test]
fn a_simulation_says_its_steps_output_and_time() {
    let e = error(&[
        "simulate",
        &robot("puma560.toml"),
        "--duration",
        "10000",
        "--csv",
        &scratch("unwritten.csv", ""),
    ]);
    contains_all(
        &e,
        &[
            "--duration / --dt: 1e7 RK4 steps, about ",
            ", and about 3.8 GB of output; a run takes at most 1e6 RK4 steps and 1.0 GB of \
             output without --no-limits",
        ],
    );
    let never = error(&["simulate", &robot("puma560.toml"), "--dt", "1e-300"]);
    assert!(
        never.contains("no run can take more than 9.01e15 RK4 steps"),
        "{never}"
    );
}

#[test]
fn samples_evaluations_periods_and_runs_are_bounded() {
    let two = robot("two_link_friction.toml");
    let e = error(&[
        "size",
        &two,
        "--from",
        "0,0",
        "--to",
        "1,1",
        "--samples",
        "100000000",
    ]);
    contains_all(
        &e,
        &[
            "--samples: 1e8 samples of the move, about ",
            "at most 1e7 samples",
        ],
    );
    let csv = scratch("unwritten.csv", "");
    let e = error(&["excite", &two, "--csv", &csv, "--evaluations", "100000000"]);
    contains_all(
        &e,
        &[
            "--evaluations, --period × --rate, --periods: 1e10 samples of the regressor \
             (100000000 evaluations of 100 samples, and the 1000 of a period twice for the \
             report)",
            "at most 1e7 samples of the regressor without --no-limits",
        ],
    );
    let e = error(&[
        "excite",
        &two,
        "--csv",
        &csv,
        "--evaluations",
        "10",
        "--periods",
        "100000",
    ]);
    contains_all(&e, &["about 14.0 GB of output", "at most 1.0 GB of output"]);
    let e = error(&["stats", &two, "--runs", "1001"]);
    assert!(
        e.contains("`1001` is not a whole number from 1 to 1000"),
        "{e}"
    );
}

/// `--duration 1e-300` printed a table of NaN (exit code 0): q̈ = Δq·60/T² overflows.
#[test]
fn a_move_too_fast_for_finite_numbers_is_refused() {
    let e = error(&[
        "size",
        &robot("two_link_friction.toml"),
        "--from",
        "0,0",
        "--to",
        "1,1",
        "--duration",
        "1e-300",
    ]);
    assert!(
        e.contains("--from, --to, --duration: a move of 1.0 (rad or m) in 1e-300 s accelerates"),
        "{e}"
    );
    assert!(e.contains("expected a finite number"), "{e}");
    // A file whose differences overflow: refused at its sample, not a table of NaN.
    let csv = scratch("overflow.csv", "t,q1,q2\n0,0,0\n1e-200,1,1\n2e-200,0,0\n");
    let e = error(&["size", &robot("two_link_friction.toml"), "--csv", &csv]);
    assert!(
        e.contains(&format!(
            "{csv}: line 2, column 2 (q1): central differences give q̇ = inf"
        )),
        "{e}"
    );
}

/// `--tolerance -1` was clap's "unexpected argument" with a tip to write `-- -1`.
#[test]
fn negative_numbers_reach_their_options() {
    let two = robot("two_link_friction.toml");
    let e = error(&["identify", &two, "--csv", "m.csv", "--tolerance", "-1"]);
    assert!(
        e.contains("invalid value '-1' for '--tolerance <FRACTION>': `-1` is not a fraction: expected a number above 0 and below 1"),
        "{e}"
    );
    let e = error(&["simulate", &two, "--dt", "-0.001"]);
    assert!(
        e.contains("`-0.001` is not positive: expected a number above 0"),
        "{e}"
    );
    let e = error(&["stats", &two, "--runs", "-1"]);
    assert!(
        e.contains("`-1` is not a whole number from 1 to 1000"),
        "{e}"
    );
    let e = error(&["size", &two, "--csv", "--json"]);
    assert!(
        e.contains("`--json` starts with `-`: expected a file"),
        "{e}"
    );
}

/// `--set` values are checked as a description's numbers are.
#[test]
fn settings_are_checked_as_a_file_s_numbers() {
    let niku = robot("niku_example_6_4.toml");
    let e = error(&[
        "eval", &niku, "--q", "0,0", "--set", "g=9.81", "--set", "l1=1", "--set", "l2=1", "--set",
        "m1=-1", "--set", "m2=1",
    ]);
    assert!(
        e.contains(
            "--set: with these values, joint 1: the mass is negative (-1): a mass is 0 or more"
        ),
        "{e}"
    );
    let e = error(&["eval", &niku, "--q", "0,0", "--set", "mass=1"]);
    assert!(
        e.contains("--set: the robot has no parameter `mass`; expected one of g, l1, l2, m1, m2"),
        "{e}"
    );
}
