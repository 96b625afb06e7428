//! Fuzzing the description-file front end: the valid robots of `robots/*.toml` and
//! `tests/data/reference/robots/*.json`, and two trees (by frames and by modified D-H rows),
//! mutated (byte flips, deletions, duplications, lines
//! spliced between files, numbers replaced by extreme values, deep nesting, long strings), go
//! through `front::load`, the command-line tool's checks after it, and the derive's
//! `file = "..."`. Each case must finish within [`fuzz::BOUND`] without a panic, and:
//! - an error of `front::load` names a line and column inside the text, unless it is about the
//!   file as a whole (no joints, an unknown extension);
//! - every `compile_error!` of the derive is on the `file = "..."` token (not the call site), and
//!   one about the file's content names `path:line:col` inside the text, unless about the whole.
//!
//! proptest, seed fixed: 1,500 cases by default (about 10 s in the debug build). Long run:
//! `DYNAMICS_FUZZ_CASES=40000 cargo test -p dynamics-codegen --test it fuzz_files -- --nocapture`.
//! Run for issue 15 (debug build, 2 cores shared with other builds): a first run, 20,000 to
//! 30,000 cases in 4:48,
//! found the JSON byte columns (a BOM in a string), fixed; then 40,000 cases in 7:45, no failure.
//! The other fixes were found by the default run: see the regression tests at the end.

use crate::fuzz;

use dynamics_codegen::{check, derive_dynamics, front};
use proptest::prelude::*;
use proptest::sample::Index;

/// A tree given by frames, parents by name and number, its last joint a mimic of the first.
const TREE_FRAMES: &str = r#"name = "hand"
gravity = [0, 0, -9.81]

[[joints]]
name = "palm"
type = "revolute"
mass = 0.5
inertia = [0.001, 0.001, 0.001, 0, 0, 0]

[[joints]]
type = "revolute"
parent = "palm"
origin = { xyz = [0.05, 0, 0], rpy = [0, "90 deg", 0] }
axis = [0, 1, 0]
mass = 0.1
com = [0, 0, 0.02]
inertia = [0.0001, 0.0001, 0.0001, 0, 0, 0]

[[joints]]
type = "prismatic"
parent = 1
origin = { xyz = [0, 0.05, 0.01], rpy = [0.3, 0, 0] }
axis = [0.6, 0.8, 0]
mass = 0.1
inertia = [0.0001, 0.0001, 0.0001, 0, 0, 0]

[[joints]]
type = "revolute"
parent = 0
origin = { xyz = [0, 0, 0.2] }
mimic = { joint = "palm", multiplier = -0.5, offset = 0.1 }
mass = 0.2
inertia = [0.001, 0.001, 0.001, 0, 0, 0]
"#;

/// A tree given by Khalil-Kleinfinger's modified D-H rows.
const TREE_ROWS: &str = r#"{"name": "tree", "convention": "modified", "gravity": [0, 0, -9.81],
  "joints": [
    {"type": "revolute", "name": "root", "a": 0.1, "mass": 1, "inertia": [0.1, 0.1, 0.1, 0, 0, 0]},
    {"type": "revolute", "alpha": "90 deg", "a": 0.2, "mass": 1, "inertia": [0.1, 0.1, 0.1, 0, 0, 0]},
    {"type": "prismatic", "parent": "root", "gamma": "-90 deg", "b": 0.05, "a": 0.3,
     "mass": 1, "com": [0, 0, 0.1], "inertia": [0.1, 0.1, 0.1, 0, 0, 0]},
    {"type": "revolute", "parent": 0, "gamma": 0.4, "b": -0.1, "d": 0.2,
     "mass": 1, "inertia": [0.1, 0.1, 0.1, 0, 0, 0]}
  ]}"#;

/// The valid description files the mutations start from.
const BASES: [(&str, &str); 20] = [
    ("tree_frames.toml", TREE_FRAMES),
    ("tree_rows.json", TREE_ROWS),
    (
        "niku_example_6_1.toml",
        include_str!("../../../robots/niku_example_6_1.toml"),
    ),
    (
        "niku_example_6_2.toml",
        include_str!("../../../robots/niku_example_6_2.toml"),
    ),
    (
        "niku_example_6_3.toml",
        include_str!("../../../robots/niku_example_6_3.toml"),
    ),
    (
        "niku_example_6_4.toml",
        include_str!("../../../robots/niku_example_6_4.toml"),
    ),
    (
        "niku_example_6_5.toml",
        include_str!("../../../robots/niku_example_6_5.toml"),
    ),
    (
        "niku_example_6_8.toml",
        include_str!("../../../robots/niku_example_6_8.toml"),
    ),
    ("panda.toml", include_str!("../../../robots/panda.toml")),
    ("puma560.toml", include_str!("../../../robots/puma560.toml")),
    (
        "stanford.toml",
        include_str!("../../../robots/stanford.toml"),
    ),
    ("ur5.toml", include_str!("../../../robots/ur5.toml")),
    (
        "niku_2link.json",
        include_str!("../../../tests/data/reference/robots/niku_2link.json"),
    ),
    (
        "niku_polar.json",
        include_str!("../../../tests/data/reference/robots/niku_polar.json"),
    ),
    (
        "puma560.json",
        include_str!("../../../tests/data/reference/robots/puma560.json"),
    ),
    (
        "random1.json",
        include_str!("../../../tests/data/reference/robots/random1.json"),
    ),
    (
        "random2.json",
        include_str!("../../../tests/data/reference/robots/random2.json"),
    ),
    (
        "random5.json",
        include_str!("../../../tests/data/reference/robots/random5.json"),
    ),
    (
        "stanford.json",
        include_str!("../../../tests/data/reference/robots/stanford.json"),
    ),
    (
        "ur5.json",
        include_str!("../../../tests/data/reference/robots/ur5.json"),
    ),
];

/// What replaces a number: extremes of f64 and of the integers, non-finite spellings, and
/// strings the value grammar reads.
const EXTREMES: [&str; 44] = [
    "1e308",
    "-1e308",
    "1e309",
    "-1e309",
    "-0",
    "-0.0",
    "0.0",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "+inf",
    "18446744073709551616",
    "-18446744073709551617",
    "9223372036854775807",
    "-9223372036854775808",
    "340282366920938463463374607431768211457",
    "1e-400",
    "4.9e-324",
    "0x7fffffffffffffff",
    "1_000",
    "true",
    "[]",
    "{}",
    "\"1e308 * 1e308\"",
    "\"-0\"",
    "\"nan\"",
    "\"inf\"",
    "\"1 / 0\"",
    "\"0 / 0\"",
    "\"q\"",
    "\"q1 + 1\"",
    "\"x\"",
    "\"m1^99999999999\"",
    "\"2^1024\"",
    "\"2^-1075\"",
    "\"10^308 * 10\"",
    "\"1e400 deg\"",
    "\"99999999999999999999999999999999999999999 deg\"",
    "\"pi^1000\"",
    "\"\"",
    "\"90 rad\"",
    "\"1e308\"",
    "\"-(-(-(1)))\"",
];

/// Short insertions: the formats' punctuation and a few keys.
const PIECES: [&str; 22] = [
    "\"",
    "[",
    "]",
    "{",
    "}",
    "=",
    ",",
    ":",
    "\n",
    "#",
    "[[joints]]\n",
    "'''",
    "\\u0000",
    "\"\\ud800\"",
    "\r",
    "\t",
    "mass = 1\n",
    "\"mass\": 1,",
    "type = \"prismatic\"\n",
    "\u{feff}",
    "é",
    "\0",
];

#[derive(Clone, Debug)]
enum Mutation {
    /// A bit flipped, bytes deleted or duplicated, a line of another base file spliced in.
    Bytes(fuzz::bytes::Bytes),
    Number {
        which: Index,
        by: Index,
    },
    /// `depth` open brackets (or parentheses in a string value) around a value.
    Nest {
        at: Index,
        depth: usize,
        kind: u8,
    },
    Long {
        at: Index,
        len: usize,
        kind: u8,
    },
    Insert(Index, Index),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => fuzz::bytes::Bytes::strategy(200).prop_map(Mutation::Bytes),
        3 => (any::<Index>(), any::<Index>()).prop_map(|(which, by)| Mutation::Number { which, by }),
        1 => (any::<Index>(), 1..4000usize, 0..4u8)
            .prop_map(|(at, depth, kind)| Mutation::Nest { at, depth, kind }),
        1 => (any::<Index>(), 1..100_000usize, 0..3u8)
            .prop_map(|(at, len, kind)| Mutation::Long { at, len, kind }),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, p)| Mutation::Insert(i, p)),
    ]
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let at = |i: &Index, text: &Vec<u8>| i.index(text.len() + 1);
    match m {
        Mutation::Bytes(bytes) => bytes.apply(text, &BASES.map(|(_, text)| text)),
        Mutation::Number { which, by } => {
            let spans = fuzz::numbers(text);
            if !spans.is_empty() {
                let (s, e) = *which.get(&spans);
                text.splice(s..e, by.get(&EXTREMES).bytes());
            }
        }
        Mutation::Nest { at: i, depth, kind } => {
            let (open, close, inner) = match kind {
                0 => ("[", "]", "1"),
                1 => ("{\"a\": ", "}", "1"),
                2 => ("{a = ", "}", "1"),
                _ => ("(", ")", "1"),
            };
            let mut nested = open.repeat(*depth) + inner + &close.repeat(*depth);
            if *kind == 3 {
                nested = format!("\"{nested}\"");
            }
            let i = at(i, text);
            text.splice(i..i, nested.bytes());
        }
        Mutation::Long { at: i, len, kind } => {
            let long = match kind {
                0 => format!("\"{}\"", "a".repeat(*len)),
                1 => "9".repeat(*len),
                _ => format!("\"{}\"", "m1 + ".repeat(*len / 5 + 1) + "1"),
            };
            let i = at(i, text);
            text.splice(i..i, long.bytes());
        }
        Mutation::Insert(i, p) => {
            let i = at(i, text);
            text.splice(i..i, p.get(&PIECES).bytes());
        }
    }
}

/// Errors about the file as a whole, which have no one place in it.
fn whole_file(message: &str) -> bool {
    message.contains("`joints` is empty") || message.contains("cannot tell the format")
}

/// Fields for the names the base files use, so that a valid file derives.
const FIELDS: &str =
    "g: f64, m: f64, m1: f64, m2: f64, l: f64, l1: f64, l2: f64, k: f64, I1act: f64, I2act: f64";

/// Loads `text` as `path` the ways the tools do; the first broken promise, if any.
fn check_file(path: &'static str, text: String) -> Result<(), String> {
    match front::load(path, &text) {
        Err(e) => match (e.line, e.column) {
            (Some(l), Some(c)) if !fuzz::Lines::of(&text).inside(l, c) => {
                return Err(format!("error outside the text: {e}"))
            }
            (None, _) | (_, None) if !whole_file(&e.message) => {
                return Err(format!("error without a position: {e}"))
            }
            _ => {}
        },
        // The command-line tool's checks after loading.
        Ok(loaded) => {
            for problem in check::robot(&loaded.robot, &loaded.check_inertia) {
                let message = loaded.describe(path, &problem);
                if !fuzz::Lines::of(&text).pointed_at(&message, path) {
                    return Err(format!("check without a position: {message}"));
                }
            }
        }
    }
    check_derive(path, &text)
}

/// The derive's `file = "..."` on `text`, written to a temporary file.
fn check_derive(path: &str, text: &str) -> Result<(), String> {
    let file = fuzz::temp_file(path, text).map_err(|e| e.to_string())?;
    let file = file.display().to_string();
    let source = format!("#[dynamics(file = \"{file}\")] struct R {{ {FIELDS} }}");
    let out = derive_dynamics(source.parse().expect("tokens"));
    let _ = std::fs::remove_file(&file);
    for e in fuzz::compile_errors(out) {
        if e.at.is_none() {
            return Err(format!("derive error on the call site: {}", e.message));
        }
        if !fuzz::Lines::of(text).pointed_at(&e.message, &file) && !whole_file(&e.message) {
            return Err(format!("derive error without a position: {}", e.message));
        }
    }
    Ok(())
}

/// Runs the mutated file through the checks on a bounded thread.
fn run(base: usize, mutations: &[Mutation]) -> Result<(), TestCaseError> {
    let (path, text) = BASES[base];
    let mut bytes = text.as_bytes().to_vec();
    for m in mutations {
        apply(&mut bytes, m);
    }
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let shown: String = text.chars().take(4000).collect();
    fuzz::bounded(&format!("{path}:\n{shown}"), move || check_file(path, text))
        .and_then(|r| r)
        .map_err(TestCaseError::fail)
}

#[test]
fn mutated_description_files() {
    let strategy = (0..BASES.len(), prop::collection::vec(mutation(), 1..5));
    fuzz::runner(15, 1500)
        .run(&strategy, |(base, mutations)| run(base, &mutations))
        .unwrap();
}

/// What the fuzzing found, fixed: each case once, with the position expected.
#[test]
fn regressions() {
    // serde_json says column 0 for an error on a newline; it is the 12th character of line 1.
    let e = front::from_text("a.json", "{\"name\": \"a\nb\"}").unwrap_err();
    assert_eq!((e.line, e.column), (Some(1), Some(12)), "{e}");
    // serde_json points at the unknown key's closing quote and counts bytes: after "é" (2 bytes)
    // that quote is byte 18 but character 17.
    let e = front::from_text("a.json", "{\"name\": \"é\", \"x\": 1}").unwrap_err();
    assert_eq!((e.line, e.column), (Some(1), Some(17)), "{e}");
    // A division by zero in a string value named the file only; it is the string on line 2,
    // column 18 (the derive and the command-line tool both read the file this way).
    let e = front::from_text("a.toml", "# x\ngravity = [0, 0, \"1 / (2 - 2)\"]\n").unwrap_err();
    assert!(e.message.contains("division by zero"), "{e}");
    assert_eq!((e.line, e.column), (Some(2), Some(18)), "{e}");
}

/// A literal of 100,000 digits took syn about a minute to read (quadratic); it is now refused.
#[test]
fn long_literal_regression() {
    let text = format!("gravity = [0, \"{}\", 0]\n", "9".repeat(100_000));
    let e = fuzz::bounded("long literal", move || {
        front::from_text("a.toml", &text).unwrap_err()
    })
    .unwrap();
    assert!(
        e.message.contains("at most 1000 characters"),
        "{}",
        &e.message[..200.min(e.message.len())]
    );
    assert_eq!(e.line, Some(1));
}

/// A field named in `gravity` that the struct lacks named the file only; the derive now points
/// at gravity's value: line 2, column 11 in TOML (after `gravity = `), column 13 in JSON.
#[test]
fn gravity_field_regression() {
    for (name, text, column) in [
        ("g.toml", "name = \"a\"\ngravity = [0, 0, \"-gz\"]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n", 11),
        ("g.json", "{\"name\": \"a\",\n \"gravity\": [0, 0, \"-gz\"], \"joints\": [{\"type\": \"revolute\", \"mass\": 1}]}", 13),
    ] {
        let file = std::env::temp_dir().join(format!("dynamics-fuzz-{}-{name}", std::process::id()));
        std::fs::write(&file, text).unwrap();
        let path = file.display().to_string();
        let source = format!("#[dynamics(file = \"{path}\")] struct R {{ g: f64 }}");
        let out = derive_dynamics(source.parse().unwrap()).to_string();
        let _ = std::fs::remove_file(&file);
        let expected = format!("{path}:2:{column}: `gz` is not a field");
        assert!(out.contains(&expected), "{expected}\n{out}");
    }
}

/// The tree bases load, as trees, so that the mutations start from the tree's paths.
#[test]
fn the_tree_bases_load_as_trees() {
    for (path, text) in &BASES[..2] {
        let robot = front::from_text(path, text).unwrap_or_else(|e| panic!("{path}: {e}"));
        assert!(robot.is_tree(), "{path}");
    }
}
