//! The algorithms run on `f64` (the numeric Newton-Euler the benchmarks compare against)
//! reproduce the reference data of every reference robot.

use dynamics_codegen::{front, numeric::Numeric};
use serde_json::Value;

#[test]
fn numeric_algorithms_match_reference_data() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/reference");
    for name in [
        "niku_2link",
        "niku_polar",
        "puma560",
        "random1",
        "random2",
        "random5",
        "stanford",
        "ur5",
    ] {
        let text = std::fs::read_to_string(format!("{dir}/robots/{name}.json")).expect("robot");
        let robot = front::from_json(&text, name).expect("json");
        let numeric = Numeric::new(&robot, &[]).expect("no fields");
        let data: Value = serde_json::from_str(
            &std::fs::read_to_string(format!("{dir}/data/{name}.json")).expect("data"),
        )
        .expect("json");
        let vec = |v: &Value| -> Vec<f64> {
            v.as_array()
                .expect("array")
                .iter()
                .map(|x| x.as_f64().expect("number"))
                .collect()
        };
        for s in data["samples"].as_array().expect("samples") {
            let (q, qd, qdd) = (vec(&s["q"]), vec(&s["qd"]), vec(&s["qdd"]));
            let tau = numeric.inverse_dynamics(&q, &qd, &qdd);
            let g = numeric.gravity_torques(&q);
            let m = numeric.mass_matrix(&q);
            let close = |a: &[f64], b: &[f64]| {
                let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
                a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-10 * scale)
            };
            assert!(close(&tau, &vec(&s["tau"])), "{name}: tau {tau:?}");
            assert!(close(&g, &vec(&s["g"])), "{name}: g {g:?}");
            for (row, want) in m.iter().zip(s["M"].as_array().expect("M")) {
                assert!(close(row, &vec(want)), "{name}: M row {row:?}");
            }
        }
    }
}
