//! Compiling what `dynamics emit` writes: Rust modules type-checked by rustc against the
//! `dynamics-runtime` this test was built with, C sources by a C compiler with the strict flags
//! of the header tests.

#![allow(dead_code)] // each test file uses its part

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The workspace root, where `dynamics` runs so that the files' paths are `robots/...`.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// Runs `dynamics` with `args` in `dir`.
pub fn dynamics_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run dynamics")
}

/// What `dynamics` with `args` prints in `dir`; panics with its error if it fails.
pub fn emitted(dir: &Path, args: &[&str]) -> String {
    let out = dynamics_in(dir, args);
    assert!(
        out.status.success(),
        "dynamics {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// An empty scratch directory of this name under the target directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    // A directory left by an earlier run: its files are rewritten below.
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir
}

/// The `dynamics-runtime` library beside this test's executable (the newest, if cargo built
/// several), which the emitted modules use.
fn runtime_library() -> (PathBuf, PathBuf) {
    let exe = std::env::current_exe().expect("the test's path");
    let deps = exe.parent().expect("the deps directory").to_path_buf();
    let library = std::fs::read_dir(&deps)
        .expect("the deps directory")
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or_default();
            name.starts_with("libdynamics_runtime-") && name.ends_with(".rlib")
        })
        .max_by_key(|p| p.metadata().and_then(|m| m.modified()).ok())
        .expect("libdynamics_runtime-*.rlib beside the test (a dependency of dynamics-cli)");
    (library, deps)
}

/// Type-checks the Rust `modules` (each a name and a module's text, as `dynamics emit`
/// writes it) as one library crate of edition 2024 (whose keywords include `gen`), warnings
/// denied; the compiler's messages if it fails.
///
/// `unused_parens` is allowed: the derivatives' emitted code has redundant parentheses, which
/// the derive's spans keep quiet but a module of one's own does not.
pub fn rustc_check(dir: &Path, modules: &[(String, String)]) -> Result<(), String> {
    let mut lib = String::new();
    for (name, text) in modules {
        std::fs::write(dir.join(format!("{name}.rs")), text).expect("write");
        lib.push_str(&format!("#[path = \"{name}.rs\"]\npub mod {name};\n"));
    }
    let source = dir.join("lib.rs");
    std::fs::write(&source, lib).expect("write");
    let (library, deps) = runtime_library();
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_owned());
    let out = Command::new(rustc)
        .args([
            "--edition",
            "2024",
            "--crate-type",
            "lib",
            "--crate-name",
            "emitted",
        ])
        .args([
            "--emit",
            "metadata",
            "-D",
            "warnings",
            "-A",
            "unused_parens",
        ])
        .arg("--extern")
        .arg(format!("dynamics_runtime={}", library.display()))
        .arg("-L")
        .arg(format!("dependency={}", deps.display()))
        .arg("--out-dir")
        .arg(dir)
        .arg(&source)
        .output()
        .expect("run rustc");
    if out.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&out.stderr).into_owned())
    }
}

/// Compiles C `source` in `dir` (where the headers it includes are) with `cc` and its
/// language `flags`, warnings as errors, into `program`; the compiler's messages if it fails.
pub fn c_compile(
    dir: &Path,
    cc: &str,
    flags: &[&str],
    source: &str,
    program: &str,
) -> Result<(), String> {
    let path = dir.join(format!("{program}.c"));
    std::fs::write(&path, source).expect("write");
    let out = Command::new(cc)
        .args(flags)
        .args([
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Werror",
            "-Wundef",
            "-O0",
        ])
        .arg("-o")
        .arg(dir.join(program))
        .arg(&path)
        .arg("-lm")
        .current_dir(dir)
        .output()
        .expect("run the compiler");
    if out.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&out.stderr).into_owned())
    }
}
