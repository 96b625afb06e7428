//! The CSV readers of every command that reads one: `identify --csv` (streamed, and held and
//! filtered with `--cutoff`), the `--validate` file of `identify`, `size --csv` and `simulate
//! --batch`, all run in this process (`dynamics_cli::run`).
//!
//! * What other programs write, a UTF-8 byte-order mark and `\r\n` line ends, reads as the
//!   plain file: the same output.
//! * Fuzzed files: random bytes, and valid files truncated, emptied or cut to their header,
//!   with `\r\n`, a byte-order mark, lines duplicated (a repeated time), swapped (time going
//!   back), dropped or added (blank, comments, short, garbage), cells replaced by NaN,
//!   infinities, huge, tiny, subnormal, empty or non-numbers, columns added or dropped, bytes
//!   that are not UTF-8, a line of more than a megabyte. Each reader must finish within
//!   [`BOUND`] without a panic, and succeed or fail with an error that names the file and a
//!   line within it, with the column for anything but a line-wide or file-wide problem (a
//!   sample count, the header's width), or a failure of the fit that names the file, or a
//!   usage error that names `--cutoff`.
//!
//! proptest, seed fixed: 96 cases, each through the five readers (a few seconds in the debug
//! build). Long run: `DYNAMICS_FUZZ_CASES=5000 cargo test -p dynamics-cli --test it cli_csv`.

use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::path::PathBuf;
use std::sync::mpsc;
use std::sync::OnceLock;
use std::time::Duration;

/// Time allowed for one reader on one file: they take milliseconds; far below a hang.
const BOUND: Duration = Duration::from_secs(20);

/// A small robot, so that each run is quick: a revolute and a prismatic joint.
const ROBOT: &str = r#"
name = "two"
gravity = [0, 0, -9.81]

[[joints]]
type = "revolute"
a = 0.5
mass = 2
com = [-0.2, 0.01, 0]
inertia = [0.01, 0.03, 0.03, 0, 0, 0]

[[joints]]
type = "prismatic"
alpha = "90 deg"
mass = 0.5
com = [0, 0, -0.05]
inertia = [0.002, 0.002, 0.001, 0, 0, 0]
"#;

fn scratch(name: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_csv");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name).to_string_lossy().into_owned()
}

fn robot() -> &'static str {
    static PATH: OnceLock<String> = OnceLock::new();
    PATH.get_or_init(|| {
        let path = scratch("two.toml");
        std::fs::write(&path, ROBOT).expect("write robot");
        path
    })
}

/// A valid file of `samples` samples at 100 Hz: `t,q1,q2,qd1,qd2,qdd1,qdd2`, then `tau1,tau2`
/// when `torques` (made up: the readers do not care).
fn valid(samples: usize, torques: bool) -> String {
    let mut text = String::from("t,q1,q2,qd1,qd2,qdd1,qdd2");
    if torques {
        text += ",tau1,tau2";
    }
    text.push('\n');
    for k in 0..samples {
        let t = k as f64 / 100.0;
        let (s, c) = (3.0 * t).sin_cos();
        let mut row = vec![t, 0.4 * s, 0.1 * c, 1.2 * c, -0.3 * s, -3.6 * s, -0.9 * c];
        if torques {
            row.extend([2.0 + s, -4.0 + 0.1 * c]);
        }
        let fields: Vec<String> = row.iter().map(f64::to_string).collect();
        text += &fields.join(",");
        text.push('\n');
    }
    text
}

/// The measurements `--validate` runs beside.
fn measured() -> &'static str {
    static PATH: OnceLock<String> = OnceLock::new();
    PATH.get_or_init(|| {
        let path = scratch("measured.csv");
        std::fs::write(&path, valid(300, true)).expect("write csv");
        path
    })
}

/// Every reader of a file at `path`: the words of its command, and whether the file has
/// torques.
fn readers(path: &str) -> Vec<(Vec<String>, bool)> {
    let robot = robot();
    let words = |w: &[&str]| w.iter().map(ToString::to_string).collect::<Vec<_>>();
    vec![
        (words(&["identify", robot, "--csv", path]), true),
        (
            words(&["identify", robot, "--csv", path, "--cutoff", "5"]),
            true,
        ),
        (
            words(&["identify", robot, "--csv", measured(), "--validate", path]),
            true,
        ),
        (words(&["size", robot, "--csv", path]), false),
        (
            words(&[
                "simulate",
                robot,
                "--batch",
                path,
                "--duration",
                "0.01",
                "--dt",
                "0.005",
            ]),
            false,
        ),
    ]
}

/// Runs `words` on a thread: its result, or why it panicked. A run longer than [`BOUND`]
/// stops the process (a hang is not worth shrinking).
fn bounded(words: Vec<String>, what: &str) -> Result<Result<String, String>, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let result = std::panic::catch_unwind(|| dynamics_cli::run(&words));
        let _ = tx.send(result);
    });
    match rx.recv_timeout(BOUND) {
        Ok(Ok(result)) => Ok(result),
        Ok(Err(payload)) => {
            let message = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_string()))
                .unwrap_or_default();
            Err(format!("panicked ({message}) on {what}"))
        }
        Err(_) => {
            eprintln!("took more than {BOUND:?} on {what}");
            std::process::abort()
        }
    }
}

#[test]
fn a_byte_order_mark_and_crlf_read_as_the_plain_file() {
    for (k, torques) in [(0, true), (1, false)] {
        let path = scratch(&format!("plain_{k}.csv"));
        let text = valid(300, torques);
        for (words, needs) in readers(&path) {
            if needs != torques {
                continue;
            }
            std::fs::write(&path, &text).expect("write");
            let plain = dynamics_cli::run(&words).expect("the plain file reads");
            for written in [
                format!("\u{feff}{text}"),
                text.replace('\n', "\r\n"),
                format!("\u{feff}{}", text.replace('\n', "\r\n")),
            ] {
                std::fs::write(&path, &written).expect("write");
                let read = dynamics_cli::run(&words);
                assert_eq!(read.as_ref(), Ok(&plain), "{words:?}");
            }
        }
    }
}

/// Finite values too large for the equations (their squares overflow) are refused at their
/// sample's line, naming the largest value's column, not printed as `inf` or `NaN`.
#[test]
fn values_too_large_for_the_equations_are_named() {
    for (torques, words) in [(true, "identify"), (false, "size")] {
        let path = scratch(&format!("huge_{words}.csv"));
        let mut lines: Vec<String> = valid(300, torques).lines().map(String::from).collect();
        // Line 6 (the header is line 1, t = 0.04 s): q̈1, the file's sixth column, 10²⁰⁰.
        let mut cells: Vec<&str> = lines[5].split(',').collect();
        cells[5] = "1e200";
        lines[5] = cells.join(",");
        std::fs::write(&path, lines.join("\n")).expect("write");
        let (words, _) = readers(&path)
            .into_iter()
            .find(|(w, t)| w[0] == words && *t == torques)
            .expect("a reader");
        let message = dynamics_cli::run(&words).expect_err("refused");
        let want = format!("{path}: line 6, column 6 (qdd1): at t = 0.04 s ");
        assert!(message.starts_with(&want), "{message}");
        assert!(message.contains("largest value is 1e200"), "{message}");
    }
}

/// What a cell may be replaced by.
const CELLS: [&str; 22] = [
    "NaN",
    "nan",
    "inf",
    "-inf",
    "infinity",
    "1e400",
    "-1e400",
    "1e-400",
    "5e-324",
    "1e308",
    "-1.7976931348623157e308",
    "1e300",
    "",
    " ",
    "x",
    "0x10",
    "1,5",
    "１",
    "\u{feff}1",
    "1e",
    "--1",
    "0.000000000000000000000000000000000000000000000000000000000000000000000000001",
];

/// What a line may be inserted as.
const LINES: [&str; 10] = [
    "",
    "# a comment",
    "   ",
    "1",
    "t,q1,q2,qd1,qd2,qdd1,qdd2",
    ",,,,,,,,",
    "0,0,0,0,0,0,0,0,0",
    "1e300,1e300,1e300,1e300,1e300,1e300,1e300,1e300,1e300",
    "\"1\",\"2\"",
    "\t\t",
];

#[derive(Clone, Debug)]
enum Mutation {
    Truncate(Index),
    Cell(Index, Index, Index),
    Duplicate(Index),
    Swap(Index, Index),
    Drop(Index),
    Insert(Index, Index),
    Crlf,
    Bom,
    /// A byte inserted, often one that is not UTF-8.
    Byte(Index, u8),
    /// A value added at the end of a line, or the last one dropped.
    Widen(Index),
    Narrow(Index),
    /// A line of more than a megabyte of digits.
    Long(Index),
    /// The file cut to its header, or emptied.
    HeaderOnly,
    Empty,
    /// The file replaced by random bytes.
    Random(Vec<u8>),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        3 => any::<Index>().prop_map(Mutation::Truncate),
        8 => (any::<Index>(), any::<Index>(), any::<Index>())
            .prop_map(|(l, c, v)| Mutation::Cell(l, c, v)),
        2 => any::<Index>().prop_map(Mutation::Duplicate),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| Mutation::Swap(a, b)),
        2 => any::<Index>().prop_map(Mutation::Drop),
        3 => (any::<Index>(), any::<Index>()).prop_map(|(at, l)| Mutation::Insert(at, l)),
        1 => Just(Mutation::Crlf),
        1 => Just(Mutation::Bom),
        3 => (any::<Index>(), any::<u8>()).prop_map(|(at, b)| Mutation::Byte(at, b)),
        2 => any::<Index>().prop_map(Mutation::Widen),
        2 => any::<Index>().prop_map(Mutation::Narrow),
        1 => Just(Mutation::HeaderOnly),
        1 => Just(Mutation::Empty),
        2 => proptest::collection::vec(any::<u8>(), 0..300).prop_map(Mutation::Random),
    ]
}

/// The lines of `text`, each with its end.
fn lines(text: &[u8]) -> Vec<Vec<u8>> {
    text.split_inclusive(|&b| b == b'\n')
        .map(<[u8]>::to_vec)
        .collect()
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let mut all = lines(text);
    let line = |i: &Index, all: &Vec<Vec<u8>>| i.index(all.len().max(1));
    match m {
        Mutation::Truncate(i) => {
            let at = i.index(text.len() + 1);
            text.truncate(at);
            return;
        }
        Mutation::Cell(l, c, v) if !all.is_empty() => {
            let l = line(l, &all);
            let body = String::from_utf8_lossy(&all[l]).trim_end().to_string();
            let mut cells: Vec<String> = body.split(',').map(String::from).collect();
            let c = c.index(cells.len());
            cells[c] = v.get(&CELLS).to_string();
            all[l] = format!("{}\n", cells.join(",")).into_bytes();
        }
        Mutation::Duplicate(l) if !all.is_empty() => {
            let l = line(l, &all);
            all.insert(l, all[l].clone());
        }
        Mutation::Swap(a, b) if !all.is_empty() => {
            let (a, b) = (line(a, &all), line(b, &all));
            all.swap(a, b);
        }
        Mutation::Drop(l) if !all.is_empty() => {
            let l = line(l, &all);
            all.remove(l);
        }
        Mutation::Insert(at, l) => {
            let at = at.index(all.len() + 1);
            all.insert(at, format!("{}\n", l.get(&LINES)).into_bytes());
        }
        Mutation::Crlf => {
            for l in &mut all {
                if l.last() == Some(&b'\n') {
                    l.insert(l.len() - 1, b'\r');
                }
            }
        }
        Mutation::Bom => all.insert(0, "\u{feff}".as_bytes().to_vec()),
        Mutation::Byte(at, b) => {
            let at = at.index(text.len() + 1);
            text.insert(at, *b);
            return;
        }
        Mutation::Widen(l) if !all.is_empty() => {
            let l = line(l, &all);
            let end = all[l].iter().rposition(|&b| b != b'\n' && b != b'\r');
            let at = end.map_or(0, |e| e + 1);
            all[l].splice(at..at, b",7".iter().copied());
        }
        Mutation::Narrow(l) if !all.is_empty() => {
            let l = line(l, &all);
            if let Some(comma) = all[l].iter().rposition(|&b| b == b',') {
                let end = all[l].iter().rposition(|&b| b != b'\n' && b != b'\r');
                all[l].drain(comma..end.map_or(comma, |e| e + 1));
            }
        }
        Mutation::Long(at) => {
            let at = at.index(all.len() + 1);
            all.insert(at, vec![b'1'; (1 << 20) + 10]);
        }
        Mutation::HeaderOnly => all.truncate(1),
        Mutation::Empty => all.clear(),
        Mutation::Random(bytes) => {
            text.clone_from(bytes);
            return;
        }
        _ => {}
    }
    *text = all.concat();
}

/// Errors about a whole line or the whole file, which have no column.
const LINE_WIDE: [&str; 5] = [
    "the header has",
    "no header",
    "samples: estimating",
    "no samples after the header",
    "longer than",
];

/// Checks what a reader said of the file `path` holding `text`.
fn judge(
    path: &str,
    text: &[u8],
    words: &[String],
    result: &Result<String, String>,
) -> Result<(), String> {
    // A simulation from an absurd state may diverge: its end is not finite, as it should be.
    let simulated = words[0] == "simulate";
    let message = match result {
        Ok(out) if !simulated && (out.contains("NaN") || out.contains("inf")) => {
            return Err(format!("not finite, without an error: {out}"));
        }
        Ok(_) => return Ok(()),
        Err(message) => message,
    };
    let at = format!("{path}: line ");
    let Some(start) = message.find(&at) else {
        // A failure of the fit on data that read, or a usage error of the cutoff.
        return if message.contains(path) || message.contains("--cutoff") {
            Ok(())
        } else {
            Err(format!("names neither the file nor --cutoff: {message}"))
        };
    };
    let rest = &message[start + at.len()..];
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    let line: usize = digits.parse().map_err(|_| format!("no line: {message}"))?;
    let lines = text.iter().filter(|&&b| b == b'\n').count() + 1;
    if line == 0 || line > lines {
        return Err(format!("line {line} of {lines}: {message}"));
    }
    let rest = &rest[digits.len()..];
    if rest.starts_with(", column ") || LINE_WIDE.iter().any(|w| rest.contains(w)) {
        Ok(())
    } else {
        Err(format!("no column: {message}"))
    }
}

fn run_case(mutations: &[Mutation], case: usize) -> Result<(), TestCaseError> {
    for (torques, name) in [(true, "fuzz_tau"), (false, "fuzz")] {
        let path = scratch(&format!("{name}_{case}.csv"));
        let mut text = valid(30, torques).into_bytes();
        for m in mutations {
            apply(&mut text, m);
        }
        std::fs::write(&path, &text).expect("write");
        for (words, needs) in readers(&path) {
            if needs != torques {
                continue;
            }
            let what = format!("{}: {mutations:?}", words.join(" "));
            let result = bounded(words.clone(), &what).map_err(TestCaseError::fail)?;
            judge(&path, &text, &words, &result)
                .map_err(|e| TestCaseError::fail(format!("{what}: {e}")))?;
        }
    }
    Ok(())
}

#[test]
fn fuzzed_files_are_read_or_refused_at_their_line() {
    let cases: u32 = std::env::var("DYNAMICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(96);
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]));
    let counter = std::sync::atomic::AtomicUsize::new(0);
    let strategy = proptest::collection::vec(mutation(), 1..5);
    let long = prop_oneof![19 => Just(None), 1 => any::<Index>().prop_map(Some)];
    runner
        .run(&(strategy, long), |(mut mutations, long)| {
            mutations.extend(long.map(Mutation::Long));
            // Cases run one after the other; each its own files, for a failure to inspect.
            let case = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            run_case(&mutations, case % 8)
        })
        .unwrap();
    assert!(counter.into_inner() >= cases as usize);
}
