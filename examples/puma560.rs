//! The PUMA 560 of the examples' library (Corke's Robotics Toolbox parameters, a textbook D-H
//! table), its closed-form dynamics evaluated, and the result compared with Pinocchio's on the
//! reference data.
//!
//! Run with `cargo run --release -p dynamics-examples --example puma560`.

use dynamics_examples::Puma560;
use dynamics_runtime::nalgebra::DynamicsNalgebra;
use dynamics_runtime::Dynamics;

fn main() {
    let puma = Puma560 { payload: 0.0 };
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

    let sample = &data["samples"][5];
    let (q, qd, qdd) = (
        vec6(&sample["q"]),
        vec6(&sample["qd"]),
        vec6(&sample["qdd"]),
    );
    let tau = puma.inverse_dynamics(&q, &qd, &qdd);
    println!("PUMA 560 at q = {q:.3?}");
    println!("  tau (N m)          = {tau:.6?}");
    println!("  tau (Pinocchio)    = {:.6?}", vec6(&sample["tau"]));
    println!("  gravity torques    = {:.6?}", puma.gravity_torques(&q));
    println!("  kinetic energy (J) = {:.6}", puma.kinetic_energy(&q, &qd));
    let m = puma.mass_matrix_na(&nalgebra::SVector::from(q));
    println!("  mass matrix M(q) =");
    for i in 0..6 {
        let row: Vec<String> = (0..6).map(|j| format!("{:>10.6}", m[(i, j)])).collect();
        println!("    {}", row.join(" "));
    }
    println!("  M positive definite: {}", m.cholesky().is_some());

    // Every sample of the reference data, every quantity.
    let mut worst: f64 = 0.0;
    for s in data["samples"].as_array().expect("samples") {
        let (q, qd, qdd) = (vec6(&s["q"]), vec6(&s["qd"]), vec6(&s["qdd"]));
        let scaled = |got: &[f64], want: &[f64]| {
            let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
            got.iter()
                .zip(want)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
                / scale
        };
        worst = worst
            .max(scaled(
                &puma.inverse_dynamics(&q, &qd, &qdd),
                &vec6(&s["tau"]),
            ))
            .max(scaled(&puma.bias_torques(&q, &qd), &vec6(&s["h"])))
            .max(scaled(&puma.gravity_torques(&q), &vec6(&s["g"])));
        let m = puma.mass_matrix(&q);
        for i in 0..6 {
            worst = worst.max(scaled(&m[i], &vec6(&s["M"][i])));
        }
    }
    println!("largest scaled difference from Pinocchio over 20 samples: {worst:.1e}");
    assert!(worst < 1e-10);

    // A payload is a field: no recompilation to change it.
    let loaded = Puma560 { payload: 2.5 };
    println!(
        "gravity torques with a 2.5 kg payload: {:.4?}",
        loaded.gravity_torques(&q)
    );
}
