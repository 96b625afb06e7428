//! The PUMA 560 without the proc macro: `emitted_puma560.rs` is the module that
//! `dynamics emit robots/puma560.toml` writes (kept current by `dynamics-cli`'s golden test),
//! included here as plain Rust and checked against Pinocchio's reference data.
//!
//! Run with `cargo run -p dynamics-examples --example emitted_puma560`.

// Kept byte for byte as `dynamics emit` writes it (prettyplease's layout, not rustfmt's).
#[rustfmt::skip]
#[path = "emitted_puma560.rs"]
mod emitted_puma560;

use dynamics_runtime::Dynamics;
use emitted_puma560::Puma560;

fn main() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/data/reference/data/puma560.json"
    );
    let data: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("reference data"))
            .expect("json");
    let vec6 = |v: &serde_json::Value| -> [f64; 6] {
        core::array::from_fn(|i| v[i].as_f64().expect("number"))
    };
    // max |got − want| / max(1, max |want|)
    let scaled = |got: &[f64], want: &[f64]| {
        let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        got.iter()
            .zip(want)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / scale
    };
    let puma = Puma560;
    let mut worst: f64 = 0.0;
    for s in data["samples"].as_array().expect("samples") {
        let (q, qd, qdd) = (vec6(&s["q"]), vec6(&s["qd"]), vec6(&s["qdd"]));
        worst = worst
            .max(scaled(
                &puma.inverse_dynamics(&q, &qd, &qdd),
                &vec6(&s["tau"]),
            ))
            .max(scaled(&puma.bias_torques(&q, &qd), &vec6(&s["h"])))
            .max(scaled(&puma.gravity_torques(&q), &vec6(&s["g"])));
        let (m, c) = (puma.mass_matrix(&q), puma.coriolis_matrix(&q, &qd));
        for i in 0..6 {
            worst = worst
                .max(scaled(&m[i], &vec6(&s["M"][i])))
                .max(scaled(&c[i], &vec6(&s["C"][i])));
        }
    }
    println!("emitted PUMA 560 module against Pinocchio, 20 samples: largest scaled difference {worst:.1e}");
    assert!(
        worst < 1e-10,
        "emitted module disagrees with the reference data"
    );
}
