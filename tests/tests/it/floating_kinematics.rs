//! The kinematic outputs of a robot on a free-flying base, derived with `base = floating`:
//! Solo 12 with its feet for frames against Pinocchio 4.1 (`tests/data/floating/
//! solo12_kinematics.json`, by `make.py`, at the states of `solo12.json`): the centre of mass
//! and its Jacobian, `A_G`, `Ȧ_G v`, and each foot's pose, Jacobian and classical `J̇ v` in
//! LOCAL and LOCAL_WORLD_ALIGNED, to 1e-12 scaled by the largest element of each.

use super::floating_base::{flat, Solo12, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{FloatingKinematics, Pose};

fn json(file: &str) -> serde_json::Value {
    let path = format!("{}/data/floating/{file}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("the data")).expect("JSON")
}

fn check(what: &str, got: Vec<f64>, expected: &serde_json::Value) {
    let expected = flat(expected);
    assert_eq!(got.len(), expected.len(), "{what}: the length");
    let error = scaled_error(&got, &expected);
    assert!(error < TOLERANCE, "{what} off by {error:e}");
}

fn rows<const N: usize>(m: &[[f64; N]]) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

#[test]
fn solo12_against_pinocchio() {
    assert_eq!(
        Solo12::FRAME_NAMES,
        ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"]
    );
    assert_eq!((Solo12::FRAME_HL_FOOT, Solo12::FRAME_COUNT), (2, 4));
    let (states, reference) = (json("solo12.json"), json("solo12_kinematics.json"));
    let states = states["samples"].as_array().expect("samples");
    let samples = reference["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    for (k, (state, e)) in states.iter().zip(samples).enumerate() {
        let q: [f64; 19] = flat(&state["q"]).try_into().expect("19");
        let v: [f64; 18] = flat(&state["v"]).try_into().expect("18");
        let at = |what: &str| format!("sample {k}: {what}");
        check(&at("com"), Solo12.center_of_mass(&q).to_vec(), &e["com"]);
        check(
            &at("Jcom"),
            rows(&Solo12.center_of_mass_jacobian(&q)),
            &e["Jcom"],
        );
        check(
            &at("Ag"),
            rows(&Solo12.centroidal_momentum_matrix(&q)),
            &e["Ag"],
        );
        let bias = Solo12.centroidal_momentum_bias(&q, &v);
        check(&at("dAg v"), bias.to_vec(), &e["dAg_v"]);
        let poses: [Pose<f64>; 4] = Solo12.frame_poses(&q);
        let world = Solo12.frame_jacobians_world_aligned(&q);
        let local = Solo12.frame_jacobians_local(&q);
        let bias_world = Solo12.frame_acceleration_biases_world_aligned(&q, &v);
        let bias_local = Solo12.frame_acceleration_biases_local(&q, &v);
        for (f, name) in Solo12::FRAME_NAMES.iter().enumerate() {
            let x = &e["frames"][name];
            let at = |what: &str| format!("sample {k}, {name}: {what}");
            check(&at("rotation"), rows(&poses[f].rotation), &x["rotation"]);
            check(
                &at("translation"),
                poses[f].position.to_vec(),
                &x["translation"],
            );
            check(&at("J world"), rows(&world[f]), &x["J_world_aligned"]);
            check(&at("J local"), rows(&local[f]), &x["J_local"]);
            check(
                &at("dJv world"),
                bias_world[f].to_vec(),
                &x["dJv_world_aligned"],
            );
            check(&at("dJv local"), bias_local[f].to_vec(), &x["dJv_local"]);
        }
    }
}

/// `A_G v` is the momentum, so its linear part is the mass times the CoM's velocity `Jcom v`,
/// in `f32` too.
#[test]
fn solo12_momentum_in_f32() {
    let states = json("solo12.json");
    let state = &states["samples"][5];
    let q: Vec<f32> = flat(&state["q"]).iter().map(|&x| x as f32).collect();
    let v: Vec<f32> = flat(&state["v"]).iter().map(|&x| x as f32).collect();
    let (q, v): ([f32; 19], [f32; 18]) = (q.try_into().expect("19"), v.try_into().expect("18"));
    let (ag, jcom) = (
        Solo12.centroidal_momentum_matrix(&q),
        Solo12.center_of_mass_jacobian(&q),
    );
    let mass = json("solo12_kinematics.json")["mass"]
        .as_f64()
        .expect("mass") as f32;
    for i in 0..3 {
        let momentum: f32 = (0..18).map(|j| ag[i][j] * v[j]).sum();
        let velocity: f32 = (0..18).map(|j| jcom[i][j] * v[j]).sum();
        assert!((momentum - mass * velocity).abs() < 1e-4 * momentum.abs().max(1.0));
    }
}
