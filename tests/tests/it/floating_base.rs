//! A robot on a free-flying base, derived from its URDF with `base = floating`: Solo 12 (four
//! legs of three joints on a flying trunk) against Pinocchio 4.1's free flyer
//! (`tests/data/floating/solo12.json`, by `make.py`): M, h, τ and g at random states with random
//! unit quaternions, to 1e-12 scaled by the largest element of each.

use dynamics_reference::scaled_error;
use dynamics_runtime::FloatingDynamics;

/// The bar: 1e-12, scaled by max(1, the largest element).
const TOLERANCE: f64 = 1e-12;

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(urdf = "../robots/urdf/floating/solo12.urdf", base = floating)]
struct Solo12;

/// The same robot with its floating body named.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating("base_link")
)]
struct Solo12Named;

fn numbers(x: &serde_json::Value) -> Vec<f64> {
    x.as_array()
        .expect("a list")
        .iter()
        .map(|e| e.as_f64().expect("a number"))
        .collect()
}

fn array<const N: usize>(x: &serde_json::Value) -> [f64; N] {
    numbers(x).try_into().expect("the length")
}

#[test]
fn solo12_against_pinocchio() {
    assert_eq!((Solo12::NQ, Solo12::NV), (19, 18));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/floating/solo12.json");
    let text = std::fs::read_to_string(path).expect("the data");
    let data: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let samples = data["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    for (k, s) in samples.iter().enumerate() {
        let (q, v, a) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["a"]),
        );
        let m: Vec<f64> = Solo12.mass_matrix(&q).iter().flatten().copied().collect();
        let expected_m: Vec<f64> = s["M"]
            .as_array()
            .expect("rows")
            .iter()
            .flat_map(numbers)
            .collect();
        let named: Vec<f64> = Solo12Named
            .mass_matrix(&q)
            .iter()
            .flatten()
            .copied()
            .collect();
        assert_eq!(m, named, "sample {k}: the root link named is the root link");
        for (what, got, expected) in [
            ("M", m, expected_m),
            ("h", Solo12.bias_forces(&q, &v).to_vec(), numbers(&s["h"])),
            (
                "tau",
                Solo12.inverse_dynamics(&q, &v, &a).to_vec(),
                numbers(&s["tau"]),
            ),
            (
                "g",
                Solo12.generalized_gravity(&q).to_vec(),
                numbers(&s["g"]),
            ),
        ] {
            let error = scaled_error(&got, &expected);
            assert!(error < TOLERANCE, "sample {k}: {what} off by {error:e}");
        }
    }
}

/// In `f32` too, at the precision of `f32`.
#[test]
fn solo12_in_f32() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/floating/solo12.json");
    let text = std::fs::read_to_string(path).expect("the data");
    let data: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let s = &data["samples"][3];
    let (q, v, a) = (
        array::<19>(&s["q"]),
        array::<18>(&s["v"]),
        array::<18>(&s["a"]),
    );
    let single = |x: &[f64]| x.iter().map(|&e| e as f32).collect::<Vec<f32>>();
    let (q32, v32, a32) = (single(&q), single(&v), single(&a));
    let tau = Solo12.inverse_dynamics(
        &q32.try_into().expect("19"),
        &v32.try_into().expect("18"),
        &a32.try_into().expect("18"),
    );
    let got: Vec<f64> = tau.iter().map(|&x| f64::from(x)).collect();
    let error = scaled_error(&got, &numbers(&s["tau"]));
    assert!(error < 1e-4, "τ in f32 off by {error:e}");
}
