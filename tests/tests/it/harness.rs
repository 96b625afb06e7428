//! A target built without a test harness (`test = false` in its `Cargo.toml`, which saves
//! `cargo test` compiling it a second time) holds no tests, unless CI runs them in a step of its
//! own (`cargo test -p <package> --lib` in `.ci/run`: the benchmark's C ABI), and a library
//! whose documentation is not tested (`doctest = false`) no examples: one added there later
//! would never run, so this fails instead.

use crate::layout::rust_files;
use std::path::{Path, PathBuf};

/// Every `Cargo.toml` under `dir`, build output aside.
fn manifests(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() && entry.file_name() != "target" && entry.file_name() != ".git" {
            manifests(&path, out);
        } else if entry.file_name() == "Cargo.toml" {
            out.push(path);
        }
    }
}

/// The sources of each `[lib]` or `[[bin]]` section of `manifest` that has the line `setting`
/// (`test = false`), one list per section, with whether the section is the library.
fn sources_saying(manifest: &Path, setting: &str) -> Vec<(bool, Vec<PathBuf>)> {
    let package = manifest.parent().expect("a package folder");
    let text = std::fs::read_to_string(manifest).expect("read Cargo.toml");
    let mut sources = Vec::new();
    for section in text.split("\n[").skip(1) {
        let (header, body) = section.split_once('\n').unwrap_or((section, ""));
        if !body.lines().any(|l| l.trim() == setting) {
            continue;
        }
        let value = |key: &str| {
            body.lines()
                .filter_map(|l| l.trim().strip_prefix(key)?.trim().strip_prefix('='))
                .map(|v| v.trim().trim_matches('"').to_string())
                .next()
        };
        match header.trim_end_matches(']').trim_start_matches('[') {
            // A library: every source but the binaries'.
            "lib" => {
                let mut files = Vec::new();
                rust_files(&package.join("src"), &mut files);
                let binary = |f: &PathBuf| {
                    f.ends_with("src/main.rs") || f.components().any(|c| c.as_os_str() == "bin")
                };
                sources.push((true, files.into_iter().filter(|f| !binary(f)).collect()));
            }
            "bin" => {
                let name = value("name").expect("a [[bin]] has a name");
                let path = value("path").unwrap_or(format!("src/bin/{name}.rs"));
                sources.push((false, vec![package.join(path)]));
            }
            _ => {}
        }
    }
    sources
}

/// Whether `.ci/run` tests the library of the package of `manifest` in a step of its own.
fn library_tested_by_ci(manifest: &Path, ci: &str) -> bool {
    let text = std::fs::read_to_string(manifest).expect("read Cargo.toml");
    // The workspace's own manifest names no package.
    let Some(name) = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("name")?.trim().strip_prefix('='))
    else {
        return false;
    };
    let step = format!("cargo test -p {} --lib", name.trim().trim_matches('"'));
    ci.lines().any(|l| l.trim() == step)
}

#[test]
fn targets_without_a_harness_hold_no_tests() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let ci = std::fs::read_to_string(root.join(".ci/run")).expect("read .ci/run");
    let mut found = Vec::new();
    manifests(&root, &mut found);
    let targets: Vec<Vec<PathBuf>> = found
        .iter()
        .flat_map(|m| {
            let by_ci = library_tested_by_ci(m, &ci);
            sources_saying(m, "test = false")
                .into_iter()
                .filter(move |(library, _)| !(by_ci && *library))
                .map(|(_, files)| files)
        })
        .collect();
    // The libraries and binaries whose manifests say so: the benchmarks', the examples', the
    // reference's, the derive's, the test support's, the command's binary, Python's, the
    // identification's, the generator's.
    assert!(targets.len() >= 10, "found only {targets:?}");
    let with_tests: Vec<String> = targets
        .iter()
        .flatten()
        .filter(|f| {
            let text = std::fs::read_to_string(f).unwrap_or_else(|e| panic!("{f:?}: {e}"));
            text.contains("#[test]") || text.contains("#[cfg(test)]")
        })
        .map(|f| f.display().to_string())
        .collect();
    assert!(
        with_tests.is_empty(),
        "these sources hold tests that `test = false` in their Cargo.toml never runs: \
         {with_tests:#?}"
    );
}

#[test]
fn libraries_without_doctests_hold_no_examples() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut found = Vec::new();
    manifests(&root, &mut found);
    let targets: Vec<PathBuf> = found
        .iter()
        .flat_map(|m| sources_saying(m, "doctest = false"))
        .flat_map(|(_, files)| files)
        .collect();
    // The derive's and Python's.
    assert!(targets.len() >= 2, "found only {targets:?}");
    let with_examples: Vec<String> = targets
        .iter()
        .filter(|f| {
            let text = std::fs::read_to_string(f).unwrap_or_else(|e| panic!("{f:?}: {e}"));
            text.lines().any(|l| {
                let l = l.trim_start();
                (l.starts_with("///") || l.starts_with("//!")) && l[3..].trim().starts_with("```")
            })
        })
        .map(|f| f.display().to_string())
        .collect();
    assert!(
        with_examples.is_empty(),
        "these sources hold examples that `doctest = false` in their Cargo.toml never runs: \
         {with_examples:#?}"
    );
}
