//! The generated code against a reference data file of `tests/data/` (Pinocchio 4.1.0; format
//! in `tests/data/reference/README.md`): for every sample, τ, M, C, h = C·q̇ + g, g, C·q̇ and
//! both energies must match to [`TOLERANCE`], scaled as max|a − b| / max(1, max|b|).
//!
//! Pinocchio's τ has no joint friction. A robot that declares friction adds it to τ: with
//! [`Friction::Added`], the expected τ is the sample's `tau` plus its `friction` (the URDF
//! files' `damping · q̇ + friction · sign(q̇)`, written by `tests/data/urdf/make.py`).

use dynamics_reference::scaled_error;
use dynamics_runtime::Dynamics;
use serde_json::Value;

/// Largest accepted scaled error.
pub const TOLERANCE: f64 = 1e-10;

/// Whether the robot's τ includes the joint friction of the data file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Friction {
    /// τ is Pinocchio's, friction-free.
    None,
    /// τ is Pinocchio's plus the sample's `friction`.
    Added,
}

/// The 20 samples of `tests/data/<file>`.
///
/// # Panics
/// If the file is missing or malformed.
#[must_use]
pub fn samples(file: &str) -> Vec<Value> {
    samples_counted(file, 20)
}

/// The `count` samples of `tests/data/<file>`.
///
/// # Panics
/// If the file is missing or malformed, or has another number of samples.
#[must_use]
pub fn samples_counted(file: &str, count: usize) -> Vec<Value> {
    let path = format!("{}/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let data: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    let samples = data["samples"].as_array().expect("samples").clone();
    assert_eq!(samples.len(), count, "{file}");
    samples
}

/// The `N` numbers of a JSON array.
///
/// # Panics
/// If `v` is not an array of `N` numbers.
#[must_use]
pub fn vector<const N: usize>(v: &Value) -> [f64; N] {
    let a = v.as_array().expect("array");
    assert_eq!(a.len(), N);
    core::array::from_fn(|i| a[i].as_f64().expect("number"))
}

/// The `N × N` numbers of a JSON array of rows.
///
/// # Panics
/// If `v` is not `N` rows of `N` numbers.
#[must_use]
pub fn matrix<const N: usize>(v: &Value) -> [[f64; N]; N] {
    let a = v.as_array().expect("array");
    core::array::from_fn(|i| vector::<N>(&a[i]))
}

/// The rows of `m`, one after the other.
#[must_use]
pub fn flat<const N: usize>(m: [[f64; N]; N]) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

/// A quantity compared: its name, the generated code's values, the data's.
pub type Compared = (&'static str, Vec<f64>, Vec<f64>);

/// τ, M, C, h, g, C·q̇ and both energies of `robot` at sample `s`, each beside the sample's. With
/// [`Friction::Added`] the robot's τ less the sample's `friction` is compared with Pinocchio's
/// friction-free τ.
///
/// # Panics
/// If the sample lacks one of its keys.
#[must_use]
pub fn quantities<R: Dynamics<N>, const N: usize>(
    robot: &R,
    s: &Value,
    friction: Friction,
) -> Vec<Compared> {
    let v = |key: &str| vector::<N>(&s[key]);
    let (q, qd, qdd, h, g) = (v("q"), v("qd"), v("qdd"), v("h"), v("g"));
    let mut tau = robot.inverse_dynamics(&q, &qd, &qdd);
    if friction == Friction::Added {
        let f = v("friction");
        (0..N).for_each(|i| tau[i] -= f[i]);
    }
    let number = |key: &str| vec![s[key].as_f64().expect("number")];
    vec![
        ("tau", tau.to_vec(), v("tau").to_vec()),
        ("M", flat(robot.mass_matrix(&q)), flat(matrix::<N>(&s["M"]))),
        (
            "C",
            flat(robot.coriolis_matrix(&q, &qd)),
            flat(matrix::<N>(&s["C"])),
        ),
        ("h", robot.bias_torques(&q, &qd).to_vec(), h.to_vec()),
        ("g", robot.gravity_torques(&q).to_vec(), g.to_vec()),
        (
            "C qd",
            robot.coriolis_torques(&q, &qd).to_vec(),
            (0..N).map(|i| h[i] - g[i]).collect(),
        ),
        (
            "kinetic energy",
            vec![robot.kinetic_energy(&q, &qd)],
            number("kinetic_energy"),
        ),
        (
            "potential energy",
            vec![robot.potential_energy(&q)],
            number("potential_energy"),
        ),
    ]
}

/// `robot` against every sample of `tests/data/<file>`; returns the worst scaled error.
///
/// # Panics
/// If a quantity is off by more than [`TOLERANCE`].
pub fn check<R: Dynamics<N>, const N: usize>(robot: &R, file: &str, friction: Friction) -> f64 {
    let mut worst = 0.0f64;
    for (k, s) in samples(file).iter().enumerate() {
        for (what, got, want) in quantities(robot, s, friction) {
            let e = scaled_error(&got, &want);
            assert!(
                e < TOLERANCE,
                "{file} sample {k}: {what} off by {e:e}\n got {got:?}\nwant {want:?}"
            );
            worst = worst.max(e);
        }
    }
    eprintln!("{file}: worst scaled error {worst:.1e}");
    worst
}
