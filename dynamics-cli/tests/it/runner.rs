//! The `dynamics` binary of this package run from the workspace root, where the tests' relative
//! paths (`robots/…`, `tests/data/…`) point, or from another directory.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The workspace root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// Runs `dynamics args` in the workspace root.
pub fn dynamics(args: &[&str]) -> Output {
    dynamics_in(&root(), args)
}

/// Runs `dynamics args` in `dir`.
pub fn dynamics_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run dynamics")
}
