//! Helpers shared by the integration tests.

use std::path::PathBuf;

use dynamics_reference::nalgebra::{DMatrix, Matrix4};
use dynamics_reference::Robot;

/// Directory of the reference data (`tests/data/reference/` of the workspace).
pub fn reference_dir() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/data/reference/"
    ))
}

/// Sorted list of the `*.json` files in `reference_dir()/sub`.
pub fn json_files(sub: &str) -> Vec<PathBuf> {
    let dir = reference_dir().join(sub);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

/// Loads `reference_dir()/robots/NAME.json`.
pub fn load_robot(name: &str) -> Robot {
    let path = reference_dir().join("robots").join(format!("{name}.json"));
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    Robot::from_json(&text).unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()))
}

/// All robots of `reference_dir()/robots/`.
pub fn all_robots() -> Vec<Robot> {
    json_files("robots")
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).expect("readable robot file");
            Robot::from_json(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
        })
        .collect()
}

pub use dynamics_reference::scaled_error;

/// Scaled error between two dynamic matrices of the same shape.
pub fn matrix_error(a: &DMatrix<f64>, b: &DMatrix<f64>) -> f64 {
    assert_eq!(a.shape(), b.shape(), "shape mismatch");
    scaled_error(a.as_slice(), b.as_slice())
}

/// Scaled error between two 4×4 matrices.
pub fn matrix4_error(a: &Matrix4<f64>, b: &Matrix4<f64>) -> f64 {
    scaled_error(a.as_slice(), b.as_slice())
}
