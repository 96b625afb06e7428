//! Mimic joints on a free-flying base: PAL's Talos with its grippers (`talos_full_v2.urdf`, 44
//! moving joints, 12 of them following a gripper joint: 32 coordinates, `NQ = 39`, `NV = 38`)
//! against Pinocchio 4.1 (`tests/data/floating/talos_full_v2_mimic.json`, by `mimic.py`, run
//! by `make.py`): its full model's M, h, τ (with the joints' friction), g, kinematics and first
//! derivatives projected with `S̃ = diag(1₆, S)`, which Pinocchio's own `JointModelMimic`
//! matches to 3.4e-16 (the data's `mimic_cross_check`): M, h, τ, g, the kinematics, `∂τ`, and
//! the forward dynamics, `M⁻¹` and `∂a` (numpy's solve of M against the LDLᵀ from the tips), to
//! 1e-12 scaled.

use super::floating_base::{array, check_against_pinocchio, flat, numbers, reference, TOLERANCE};
use super::floating_derivatives::with_room;
use dynamics_reference::scaled_error;
use dynamics_runtime::{FloatingDynamics, FloatingDynamicsDerivatives, FloatingKinematics};

/// Talos with its grippers, two fingertips (below mimic joints) and a sole for frames.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/talos_full_v2.urdf",
    base = floating,
    derivatives = true,
    tips = ["left_sole_link", "gripper_left_fingertip_3_link", "gripper_right_fingertip_1_link"]
)]
struct Talos;

const NAME: &str = "talos_full_v2_mimic";

/// `got` against `expected` to [`TOLERANCE`], scaled; the error.
fn check(what: &str, got: &[f64], expected: &serde_json::Value) -> f64 {
    let expected = flat(expected);
    assert_eq!(got.len(), expected.len(), "{what}: the length");
    let error = scaled_error(got, &expected);
    assert!(error < TOLERANCE, "{what} off by {error:e}");
    error
}

fn rows<const N: usize>(m: &[[f64; N]]) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

fn samples() -> Vec<serde_json::Value> {
    let data = reference(NAME);
    assert_eq!(data["mimic"].as_array().map(Vec::len), Some(12));
    data["samples"].as_array().expect("samples").clone()
}

#[test]
fn talos_with_mimic_grippers_against_pinocchio() {
    assert_eq!((Talos::NQ, Talos::NV), (39, 38));
    with_room(|| check_against_pinocchio(&Talos, NAME));
}

#[test]
fn talos_forward_dynamics_and_inverse_mass() {
    with_room(|| {
        let mut worst: f64 = 0.0;
        for (k, s) in samples().iter().enumerate() {
            let (q, v, tau) = (
                array::<39>(&s["q"]),
                array::<38>(&s["v"]),
                array::<38>(&s["tau_in"]),
            );
            let a = Talos.forward_dynamics(&q, &v, &tau).expect("M");
            worst = worst.max(check(&format!("{k}: a"), &a, &s["a_fd"]));
            let inverse = Talos.mass_matrix_inverse(&q).expect("M");
            worst = worst.max(check(&format!("{k}: M⁻¹"), &rows(&inverse), &s["M_inv"]));
            let back = Talos.inverse_dynamics(&q, &v, &a);
            let error = scaled_error(&back, &numbers(&s["tau_in"]));
            assert!(error < TOLERANCE, "{k}: τ(a) off by {error:e}");
        }
        eprintln!("Talos with mimic joints, forward dynamics and M⁻¹: worst {worst:e}");
    });
}

#[test]
fn talos_kinematics_in_the_coordinates() {
    assert_eq!(Talos::FRAME_COUNT, 3);
    with_room(|| {
        for (k, s) in samples().iter().enumerate() {
            let (q, v) = (array::<39>(&s["q"]), array::<38>(&s["v"]));
            let e = &s["kinematics"];
            let at = |what: &str| format!("sample {k}: {what}");
            check(&at("com"), &Talos.center_of_mass(&q), &e["com"]);
            let jcom = rows(&Talos.center_of_mass_jacobian(&q));
            check(&at("Jcom"), &jcom, &e["Jcom"]);
            let ag = rows(&Talos.centroidal_momentum_matrix(&q));
            check(&at("Ag"), &ag, &e["Ag"]);
            let bias = Talos.centroidal_momentum_bias(&q, &v);
            check(&at("dAg v"), &bias, &e["dAg_v"]);
            let poses = Talos.frame_poses(&q);
            let world = Talos.frame_jacobians_world_aligned(&q);
            let local = Talos.frame_jacobians_local(&q);
            let bias_world = Talos.frame_acceleration_biases_world_aligned(&q, &v);
            let bias_local = Talos.frame_acceleration_biases_local(&q, &v);
            for (f, name) in Talos::FRAME_NAMES.iter().enumerate() {
                let x = &e["frames"][name];
                let at = |what: &str| format!("sample {k}, {name}: {what}");
                let rotation = rows(&poses[f].rotation);
                check(&at("rotation"), &rotation, &x["rotation"]);
                let position = poses[f].position;
                check(&at("position"), &position, &x["translation"]);
                check(&at("J world"), &rows(&world[f]), &x["J_world_aligned"]);
                check(&at("J local"), &rows(&local[f]), &x["J_local"]);
                check(&at("dJv world"), &bias_world[f], &x["dJv_world_aligned"]);
                check(&at("dJv local"), &bias_local[f], &x["dJv_local"]);
            }
        }
    });
}

#[test]
fn talos_derivatives_by_the_chain_rule() {
    with_room(|| {
        let mut worst = [0.0_f64; 2];
        for (k, s) in samples().iter().enumerate() {
            let (q, v, a, tau) = (
                array::<39>(&s["q"]),
                array::<38>(&s["v"]),
                array::<38>(&s["a"]),
                array::<38>(&s["tau_in"]),
            );
            let d = &s["derivatives"];
            let inverse = Talos.inverse_dynamics_derivatives(&q, &v, &a);
            let forward = Talos.forward_dynamics_derivatives(&q, &v, &tau).expect("M");
            for (what, got, key) in [
                ("dtau_dq", rows(&inverse.dtau_dq), "dtau_dq"),
                ("dtau_dv", rows(&inverse.dtau_dqd), "dtau_dv"),
                ("da_dq", rows(&forward.dqdd_dq), "ddq_dq"),
                ("da_dv", rows(&forward.dqdd_dqd), "ddq_dv"),
                ("da_dtau", rows(&forward.dqdd_dtau), "ddq_dtau"),
            ] {
                let error = check(&format!("{k}: {what}"), &got, &d[key]);
                let slot = usize::from(what.starts_with("da"));
                worst[slot] = worst[slot].max(error);
            }
            check(&format!("{k}: a"), &forward.qdd, &s["a_fd"]);
        }
        eprintln!(
            "Talos with mimic joints, ∂τ worst {:e}, ∂a worst {:e}",
            worst[0], worst[1]
        );
    });
}
