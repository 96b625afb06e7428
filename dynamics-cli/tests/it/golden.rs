//! Golden files: what `dynamics` prints for the repository's description files, committed and
//! compared with what it prints now.
//!
//! * `tests/golden/NAME.txt` and `NAME.tex`: `dynamics inspect` (and `--latex`) for every book
//!   example `robots/niku_example_*.toml` and for `robots/puma560.toml`;
//! * `tests/golden/NAME.kinematics.txt` and `.tex`: `dynamics inspect --kinematics` (the hand
//!   pose and Jacobians) for the book's 2-link arm (`niku_example_6_4`) and a 3R articulated
//!   arm (`robots/articulated_3r.toml`);
//! * `examples/emitted_puma560.rs`: `dynamics emit robots/puma560.toml`, which cargo also
//!   compiles and runs as part of the `emitted_puma560` example, so the emitted module is
//!   known to build;
//! * `tests/golden/puma560.h`: `dynamics emit --lang c robots/puma560.toml`, the C header
//!   (which `tests/it/c_header.rs` compiles and checks), and `tests/golden/arm_urdf.h`, a
//!   URDF's (`dynamics-runtime/tests/ui/urdf/arm.urdf`);
//! * `tests/golden/two_legs.floating.txt`, `.tex` and `.h`: `dynamics inspect --floating` (and
//!   `--latex`) and `dynamics emit --lang c --floating` for a two-legged toy on a floating base
//!   (`tests/data/floating/two_legs.urdf`).
//!
//! A stale file fails the test with a line diff. After a deliberate change, refresh them all:
//!
//! ```text
//! DYNAMICS_BLESS=1 cargo test -p dynamics-cli --test it golden
//! ```
//!
//! and review the change with `git diff`.

use dynamics_test_support::Scratch;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace root: the tool runs there, so the paths in its output are relative to it.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// One golden file: the `dynamics` arguments and the committed file (relative to the root).
struct Case {
    args: Vec<String>,
    file: String,
}

fn cases() -> Vec<Case> {
    let mut robots: Vec<String> = std::fs::read_dir(root().join("robots"))
        .expect("robots/")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|f| f.starts_with("niku_example_") && f.ends_with(".toml"))
        .collect();
    robots.sort();
    robots.push("puma560.toml".into());
    robots.push("two_link_friction.toml".into());
    let mut cases = Vec::new();
    for r in &robots {
        let stem = r.trim_end_matches(".toml");
        let path = format!("robots/{r}");
        cases.push(Case {
            args: vec!["inspect".into(), path.clone()],
            file: format!("dynamics-cli/tests/golden/{stem}.txt"),
        });
        cases.push(Case {
            args: vec!["inspect".into(), path, "--latex".into()],
            file: format!("dynamics-cli/tests/golden/{stem}.tex"),
        });
    }
    // The hand pose and Jacobians: the book's 2-link arm and a 3R articulated arm.
    for stem in ["niku_example_6_4", "articulated_3r"] {
        for (format, ext) in [(None, "txt"), (Some("--latex"), "tex")] {
            let mut args = vec!["inspect".into(), format!("robots/{stem}.toml")];
            args.push("--kinematics".into());
            args.extend(format.map(String::from));
            cases.push(Case {
                args,
                file: format!("dynamics-cli/tests/golden/{stem}.kinematics.{ext}"),
            });
        }
    }
    cases.push(Case {
        args: vec!["emit".into(), "robots/puma560.toml".into()],
        file: "examples/emitted_puma560.rs".into(),
    });
    // The C header: compiled and checked against Pinocchio by `tests/it/c_header.rs`.
    cases.push(Case {
        args: ["emit", "--lang", "c", "robots/puma560.toml"]
            .map(String::from)
            .to_vec(),
        file: "dynamics-cli/tests/golden/puma560.h".into(),
    });
    // A URDF's: its chain, names and placements read from the URDF.
    cases.push(Case {
        args: [
            "emit",
            "--lang",
            "c",
            "dynamics-runtime/tests/ui/urdf/arm.urdf",
        ]
        .map(String::from)
        .to_vec(),
        file: "dynamics-cli/tests/golden/arm_urdf.h".into(),
    });
    // A floating base's equations and C header: a two-legged toy (`tests/it/cli_floating.rs`
    // and `c_floating.rs` check Solo 12's against Pinocchio).
    let toy = "tests/data/floating/two_legs.urdf";
    for (args, ext) in [
        (vec!["inspect", toy, "--floating"], "txt"),
        (vec!["inspect", toy, "--floating", "--latex"], "tex"),
        (vec!["emit", "--lang", "c", toy, "--floating"], "h"),
    ] {
        cases.push(Case {
            args: args.into_iter().map(String::from).collect(),
            file: format!("dynamics-cli/tests/golden/two_legs.floating.{ext}"),
        });
    }
    cases
}

fn run(args: &[String]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("run dynamics");
    assert!(
        out.status.success(),
        "dynamics {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// A line diff of `old` → `new` (longest common subsequence), at most `limit` changed lines
/// shown, each with its line number in the old or new text.
fn diff(old: &str, new: &str, limit: usize) -> String {
    let a: Vec<&str> = old.lines().collect();
    let b: Vec<&str> = new.lines().collect();
    // lcs[i][j]: longest common subsequence of a[i..] and b[j..]
    let mut lcs = vec![vec![0u32; b.len() + 1]; a.len() + 1];
    for i in (0..a.len()).rev() {
        for j in (0..b.len()).rev() {
            lcs[i][j] = if a[i] == b[j] {
                lcs[i + 1][j + 1] + 1
            } else {
                lcs[i + 1][j].max(lcs[i][j + 1])
            };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut lines = Vec::new();
    while i < a.len() || j < b.len() {
        if i < a.len() && j < b.len() && a[i] == b[j] {
            i += 1;
            j += 1;
        } else if i < a.len() && (j == b.len() || lcs[i + 1][j] >= lcs[i][j + 1]) {
            lines.push(format!("-{:>5} | {}", i + 1, a[i]));
            i += 1;
        } else {
            lines.push(format!("+{:>5} | {}", j + 1, b[j]));
            j += 1;
        }
    }
    let more = lines.len().saturating_sub(limit);
    lines.truncate(limit);
    if more > 0 {
        lines.push(format!("… and {more} more changed lines"));
    }
    lines.join("\n")
}

/// Compares `actual` with the committed `file`; `Err` with a diff when it differs.
fn check(file: &Path, actual: &str) -> Result<(), String> {
    let committed = match std::fs::read_to_string(file) {
        Ok(c) => c,
        Err(e) => return Err(format!("{}: {e}", file.display())),
    };
    if committed == actual {
        return Ok(());
    }
    Err(format!(
        "{} is stale (- committed, + now):\n{}",
        file.display(),
        diff(&committed, actual, 40)
    ))
}

#[test]
fn golden_files_are_current() {
    let bless = std::env::var_os("DYNAMICS_BLESS").is_some_and(|v| v != "0");
    let mut failures = Vec::new();
    for case in cases() {
        let actual = run(&case.args);
        let file = root().join(&case.file);
        if bless {
            std::fs::create_dir_all(file.parent().expect("parent")).expect("create golden dir");
            std::fs::write(&file, &actual).expect("write golden file");
        } else if let Err(e) = check(&file, &actual) {
            failures.push(format!("`dynamics {}`: {e}", case.args.join(" ")));
        }
    }
    assert!(
        failures.is_empty(),
        "{}\n\nIf the change is intended, refresh the files with\n  \
         DYNAMICS_BLESS=1 cargo test -p dynamics-cli --test it golden\nand review `git diff`.",
        failures.join("\n\n")
    );
}

/// Every file in `tests/golden/` belongs to a case: one left behind by a removed description
/// file would otherwise go stale unnoticed.
#[test]
fn no_orphan_golden_files() {
    let expected: Vec<PathBuf> = cases().iter().map(|c| root().join(&c.file)).collect();
    let dir = root().join("dynamics-cli/tests/golden");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return; // nothing committed yet: `golden_files_are_current` reports it
    };
    for e in entries {
        let path = e.expect("entry").path();
        assert!(
            expected.contains(&path),
            "{} matches no description file; delete it",
            path.display()
        );
    }
}

/// A stale file is caught, and the message shows the changed line.
#[test]
fn stale_file_is_reported_with_a_diff() {
    let case = &cases()[0];
    let actual = run(&case.args);
    let dir = Scratch::new("golden");
    let stale = actual.replacen("D11 = ", "D11 = 2 ", 1);
    assert_ne!(stale, actual, "the example prints D11");
    let file = dir.write("stale.txt", &stale);
    let err = check(&file, &actual).expect_err("a stale file must fail");
    let line = actual
        .lines()
        .find(|l| l.contains("D11 = "))
        .expect("D11 line");
    assert!(err.contains(&format!("| {line}")), "{err}");
    assert!(err.contains("D11 = 2 "), "{err}");
    std::fs::write(&file, &actual).expect("write");
    assert_eq!(check(&file, &actual), Ok(()));
}

#[test]
fn diff_shows_only_changed_lines() {
    let d = diff("a\nb\nc\nd\n", "a\nx\nc\nd\ne\n", 10);
    assert_eq!(d, "-    2 | b\n+    2 | x\n+    5 | e");
}

/// Entries of the kinematics goldens derived by hand, so that blessing cannot hide an error.
///
/// The 3R arm (standard D-H: α1 = 90°, a2, a3): `A1 A2 A3` has the last column
/// `p = (C1(a2 C2 + a3 C23), S1(a2 C2 + a3 C23), a2 S2 + a3 S23)`, and `n`, the x axis of
/// frame 3, is `(C1 C23, S1 C23, S23)`. ᴴJ's column 2: joint 2 turns about z1 = z3 the hand at
/// `a2 x2 + a3 x3` from its axis; in the hand's axes `x2 = (C3, −S3, 0)` and `x3 = (1, 0, 0)`, so
/// `z × r = a2 (S3, C3, 0) + a3 (0, 1, 0)`: `ᴴJ12 = a2 S3`, `ᴴJ22 = a3 + a2 C3`, `ᴴJ32 = 0`.
/// The book's 2-link arm (Example 6.4): `px = l1 C1 + l2 C12`, and joint 2 moves the hand at
/// `l2 (−S12, C12)`.
#[test]
fn kinematics_entries_match_a_hand_derivation() {
    let three = run(&[
        "inspect".into(),
        "robots/articulated_3r.toml".into(),
        "--kinematics".into(),
    ]);
    for line in [
        "  nx = C1 C23",
        "  ny = S1 C23",
        "  nz = S23",
        "  px = C1(a2 C2 + a3 C23)",
        "  py = S1(a2 C2 + a3 C23)",
        "  pz = a2 S2 + a3 S23",
        "  ᴴJ12 = a2 S3",
        "  ᴴJ22 = a3 + a2 C3",
        "  ᴴJ32 = 0",
    ] {
        assert!(three.lines().any(|l| l == line), "{line} in\n{three}");
    }
    let two = run(&[
        "inspect".into(),
        "robots/niku_example_6_4.toml".into(),
        "--kinematics".into(),
    ]);
    for line in ["  px = l1 C1 + l2 C12", "  J12 = -l2 S12", "  J22 = l2 C12"] {
        assert!(two.lines().any(|l| l == line), "{line} in\n{two}");
    }
}
