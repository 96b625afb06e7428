//! A robot with a mimic joint through the commands that describe and simplify it: the small
//! mimic arm (`tests/data/trees/mimic_arm.toml`: 4 joints, the third following the second, so 3
//! coordinates). `stats` counts its coordinates and joints; `stats`, `inspect` and `emit`
//! (Rust and C) build its simplified models, one tolerance and range per coordinate, with the
//! mimic joint's `sin(−0.7 q2 + c)` bounded through its rule, and state the same bounds.

use crate::runner::dynamics;
use std::collections::BTreeSet;
use std::process::Output;

const ARM: &str = "tests/data/trees/mimic_arm.toml";

/// The request of the tests of the simplified models (one value per coordinate, or one for all).
const REQUEST: [&str; 10] = [
    "--simplified",
    "--tolerance",
    "0.1,0.25,0.003",
    "--q-min",
    "-1",
    "--q-max",
    "1.5",
    "--qdd-max",
    "5",
    "--qd-max=2",
];

fn stdout(out: &Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "failed: {err}");
    String::from_utf8(out.stdout.clone()).expect("UTF-8")
}

/// The elements a text states a bound for (`|T1 − T1,simplified| ≤ 4.2e-1`, `<=` in C).
fn bounded(text: &str, sign: &str) -> BTreeSet<String> {
    let parts: Vec<&str> = text.split(&format!(",simplified| {sign} ")).collect();
    parts[..parts.len() - 1]
        .iter()
        .map(|p| {
            p.rsplit('|')
                .next()
                .expect("a name")
                .split(' ')
                .next()
                .unwrap()
                .to_owned()
        })
        .collect()
}

#[test]
fn the_commands_count_and_simplify_a_mimic_robot() {
    let stats = stdout(&dynamics(&["stats", ARM, "--runs", "1"]));
    let first = stats.lines().next().expect("a line");
    assert!(
        first.starts_with("mimic_arm: 3 coordinates (4 joints, 1 of them mimic), graph "),
        "{first}"
    );
    let mut args = vec!["stats", ARM, "--runs", "1"];
    args.extend(REQUEST);
    let simplified = stdout(&dynamics(&args));
    for method in ["inverse_dynamics_simplified", "mass_matrix_simplified"] {
        assert!(simplified.contains(&format!("\n{method} ")), "{simplified}");
    }
    let mut args = vec!["inspect", ARM];
    args.extend(REQUEST);
    let inspect = stdout(&dynamics(&args));
    // The mimic joint's angle in its coordinate's q2 (its offset and θ offset summed); the
    // spring on it reads q2 itself, a revolute coordinate's, not a prismatic `d2`.
    assert!(inspect.contains(" sin(-7/10 q2 - 0.897"), "{inspect}");
    assert!(
        inspect.contains(" q2 ") && !inspect.contains(" d2 "),
        "{inspect}"
    );
    // A list of one per joint (4) is refused: the lists are per coordinate.
    let mut args = vec!["inspect", ARM];
    args.extend(REQUEST);
    args[4] = "0.1,0.25,0.003,0.1";
    let out = dynamics(&args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("one for each of the 3 coordinates"), "{err}");
    // `emit` reads the file's table: Rust and C state bounds for the same elements, every
    // one of the three coordinates'.
    let rust = stdout(&dynamics(&["emit", ARM]));
    let c = stdout(&dynamics(&["emit", "--lang", "c", ARM]));
    let elements = bounded(&rust, "≤");
    for name in ["T1", "T2", "T3", "D1", "D3", "C3", "D11", "D33"] {
        assert!(elements.contains(name), "{name}: {elements:?}");
    }
    assert!(!elements.contains("T4"), "{elements:?}");
    assert_eq!(bounded(&c, "<="), elements);
    assert!(
        c.contains("mimic_arm_inverse_dynamics_simplified("),
        "{}",
        &c[..300]
    );
}

/// `eval`'s lists are one value per coordinate, and a wrong count names the coordinates and
/// the joints beside them (a serial robot's message unchanged); `inspect`'s legend explains the
/// mimic joint's `sin(k qj + c)` (and a robot without mimic joints has no such line).
#[test]
fn eval_counts_coordinates_and_inspect_explains_the_mimic_notation() {
    let out = dynamics(&["eval", ARM, "--q", "0.1,0.2,0.3,0.4"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let counted = "--q: 4 values given, the robot has 3 coordinates (4 joints, 1 of them mimic)";
    assert!(err.contains(counted), "{err}");
    let out = dynamics(&["eval", ARM, "--q", "0.1,0.2,0.3", "--qd", "1,2"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--qd: 2 values given, the robot has 3 coordinates"),
        "{err}"
    );
    stdout(&dynamics(&["eval", ARM, "--q", "0.1,0.2,0.3"]));
    let out = dynamics(&["eval", "robots/puma560.toml", "--q", "0,0"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--q: 2 values given, the robot has 6 joints"),
        "{err}"
    );
    let legend = "a mimic joint follows joint j: sin(k qj + c), cos(k qj + c)";
    let inspect = stdout(&dynamics(&["inspect", ARM]));
    let header: Vec<&str> = inspect.lines().take(6).collect();
    assert!(header.iter().any(|l| l.starts_with(legend)), "{inspect}");
    let kinematics = stdout(&dynamics(&["inspect", "--kinematics", ARM]));
    assert!(kinematics.contains(legend), "{kinematics}");
    let serial = stdout(&dynamics(&["inspect", "robots/puma560.toml"]));
    assert!(!serial.contains("mimic"), "{serial}");
}
