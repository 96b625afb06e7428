//! The floating-base kinematic outputs of Solo 12 against Pinocchio 4.1
//! (`tests/data/floating/solo12_kinematics.json`, by `make.py`): the centre of mass and its
//! Jacobian, `A_G`, `Ȧ_G v`, and each foot's pose, Jacobian and classical `J̇ v` in LOCAL and
//! LOCAL_WORLD_ALIGNED, to 1e-12 scaled by the largest entry of each.

use super::floating_tests::numeric_base;
use super::tree_tests::{chain, At};
use dynamics_codegen::algo::{
    acceleration_bias_in_base, centroidal, centroidal_bias, floating_frame, jacobian_in_base,
    tip_kinematics,
};
use dynamics_codegen::model::{FreeFlyer, Robot};
use serde_json::Value as Json;

pub(crate) const FEET: [&str; 4] = ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"];

/// Solo 12 with its feet for tips, and its floating body.
pub(crate) fn solo12_with_feet() -> (Robot, FreeFlyer) {
    let path = format!(
        "{}/../robots/urdf/floating/solo12.urdf",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the URDF");
    let request = dynamics_codegen::front::Chain {
        tips: &FEET,
        ..Default::default()
    };
    let loaded = dynamics_codegen::front::load_urdf(&path, &text, request, true).expect("loads");
    let flyer = dynamics_codegen::front::free_flyer(&text, None).expect("a floating body");
    (loaded.robot, flyer)
}

pub(crate) fn data(file: &str) -> Json {
    let path = format!(
        "{}/../tests/data/floating/{file}",
        env!("CARGO_MANIFEST_DIR")
    );
    serde_json::from_str(&std::fs::read_to_string(path).expect("the data")).expect("JSON")
}

/// The numbers of `x`, a list or a list of lists, flattened.
pub(crate) fn flat(x: &Json) -> Vec<f64> {
    match x {
        Json::Array(items) => items.iter().flat_map(flat).collect(),
        _ => vec![x.as_f64().expect("a number")],
    }
}

pub(crate) fn check(what: &str, got: &[f64], expected: &Json) {
    let expected = flat(expected);
    assert_eq!(got.len(), expected.len(), "{what}: the length");
    let scale = expected.iter().fold(1.0f64, |x, e| x.max(e.abs()));
    for (k, (x, e)) in got.iter().zip(&expected).enumerate() {
        assert!((x - e).abs() <= 1e-12 * scale, "{what}[{k}]: {x} vs {e}");
    }
}

#[test]
fn solo12_against_pinocchio() {
    let (robot, flyer) = solo12_with_feet();
    let tips = robot.tip_frames();
    let names: Vec<&str> = tips.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, FEET);
    let base = numeric_base(&robot, &flyer);
    let (states, reference) = (data("solo12.json"), data("solo12_kinematics.json"));
    let states = states["samples"].as_array().expect("samples");
    let samples = reference["samples"].as_array().expect("samples");
    assert_eq!(states.len(), samples.len());
    for (k, (state, expected)) in states.iter().zip(samples).enumerate() {
        let (q, v) = (flat(&state["q"]), flat(&state["v"]));
        let joints = &q[7..];
        let quaternion = [q[3], q[4], q[5], q[6]];
        let c = chain(&robot, joints);
        let centroidal = centroidal(&c, &base, quaternion);
        let com =
            [0, 1, 2].map(|i| q[i] + [centroidal.com.x, centroidal.com.y, centroidal.com.z][i]);
        check(&format!("#{k} com"), &com, &expected["com"]);
        check(
            &format!("#{k} Jcom"),
            &centroidal.com_jacobian.concat(),
            &expected["Jcom"],
        );
        check(
            &format!("#{k} Ag"),
            &centroidal.matrix.concat(),
            &expected["Ag"],
        );
        let bias = centroidal_bias(&c, &base, quaternion, &v, centroidal.com_in_base);
        check(&format!("#{k} dAg v"), &bias, &expected["dAg_v"]);
        for tip in &tips {
            let e = &expected["frames"][&tip.name];
            let what = |x: &str| format!("#{k} {} {x}", tip.name);
            let kin = tip_kinematics(&mut At(joints), &robot, tip);
            let jacobian = jacobian_in_base(&kin);
            let fixed_bias = acceleration_bias_in_base(&kin, &jacobian, &v[6..]);
            let frame = floating_frame(&kin, &jacobian, &fixed_bias, quaternion, &v);
            let rotation: Vec<f64> = frame.rotation.m.concat();
            check(&what("rotation"), &rotation, &e["rotation"]);
            let p = frame.position;
            let position = [q[0] + p.x, q[1] + p.y, q[2] + p.z];
            check(&what("translation"), &position, &e["translation"]);
            check(
                &what("J local"),
                &frame.jacobian_local.concat(),
                &e["J_local"],
            );
            check(
                &what("J world"),
                &frame.jacobian_world.concat(),
                &e["J_world_aligned"],
            );
            check(&what("dJv local"), &frame.bias_local, &e["dJv_local"]);
            check(
                &what("dJv world"),
                &frame.bias_world,
                &e["dJv_world_aligned"],
            );
        }
    }
}
