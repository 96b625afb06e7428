//! Contacts at the feet of a robot on a free-flying base (`FloatingContacts`): Solo 12 against
//! Pinocchio 4.1 (`tests/data/floating/solo12_contacts.json`, by `make.py`'s `contacts`, at the
//! states of `solo12.json`): `rnea` and `aba` with external wrenches and point forces at the
//! feet, and `constraintDynamics` with CONTACT_3D at the feet in contact (a set per sample), to
//! 1e-12 scaled by the largest element of each; and the constraint itself, `J a + J̇ v = 0` at
//! the feet in contact, and `τ` given back by inverse dynamics with the contact forces.

use super::floating_base::{array, numbers, reference, Solo12, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{ContactError, FloatingContacts, FloatingDynamics, FloatingKinematics};

fn check(what: &str, got: &[f64], expected: &[f64]) {
    assert_eq!(got.len(), expected.len(), "{what}: the length");
    let error = scaled_error(got, expected);
    assert!(error < TOLERANCE, "{what} off by {error:e}");
}

fn rows<const N: usize, const F: usize>(x: &serde_json::Value) -> [[f64; N]; F] {
    let rows: Vec<[f64; N]> = x.as_array().expect("rows").iter().map(array).collect();
    rows.try_into().expect("a row per frame")
}

/// The states of `solo12.json` beside their contact data.
fn samples() -> Vec<(serde_json::Value, serde_json::Value)> {
    let states = reference("solo12")["samples"]
        .as_array()
        .expect("samples")
        .clone();
    let contacts = reference("solo12_contacts")["samples"]
        .as_array()
        .expect("samples")
        .clone();
    assert_eq!(states.len(), contacts.len());
    assert!(states.len() >= 10);
    states.into_iter().zip(contacts).collect()
}

#[test]
fn wrenches_and_forces_against_pinocchio() {
    for (k, (s, c)) in samples().iter().enumerate() {
        let (q, v, a, tau) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["a"]),
            array::<18>(&s["tau"]),
        );
        let wrenches: [[f64; 6]; 4] = rows(&c["wrenches"]);
        let forces: [[f64; 3]; 4] = rows(&c["forces"]);
        let at = |what: &str| format!("sample {k}: {what}");
        let got = Solo12.inverse_dynamics_with_wrenches(&q, &v, &a, &wrenches);
        check(
            &at("rnea with wrenches"),
            &got,
            &numbers(&c["tau_wrenches"]),
        );
        let got = Solo12.inverse_dynamics_with_forces(&q, &v, &a, &forces);
        check(&at("rnea with forces"), &got, &numbers(&c["tau_forces"]));
        let got = Solo12
            .forward_dynamics_with_wrenches(&q, &v, &tau, &wrenches)
            .expect("M is positive definite");
        check(&at("aba with wrenches"), &got, &numbers(&c["a_wrenches"]));
        let got = Solo12
            .forward_dynamics_with_forces(&q, &v, &tau, &forces)
            .expect("M is positive definite");
        check(&at("aba with forces"), &got, &numbers(&c["a_forces"]));
    }
}

#[test]
fn contact_dynamics_against_pinocchio() {
    for (k, (s, c)) in samples().iter().enumerate() {
        let (q, v, tau) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["tau"]),
        );
        let in_contact: [bool; 4] = c["in_contact"]
            .as_array()
            .expect("a mask")
            .iter()
            .map(|b| b.as_bool().expect("a bool"))
            .collect::<Vec<_>>()
            .try_into()
            .expect("a flag per foot");
        let at = |what: &str| format!("sample {k}, {in_contact:?}: {what}");
        let got = Solo12
            .contact_dynamics(&q, &v, &tau, &in_contact)
            .expect("independent contacts");
        check(&at("ddq"), &got.acceleration, &numbers(&c["a_contact"]));
        let forces: Vec<f64> = got.forces.iter().flatten().copied().collect();
        let expected: Vec<f64> = rows::<3, 4>(&c["lambda"])
            .iter()
            .flatten()
            .copied()
            .collect();
        check(&at("lambda"), &forces, &expected);
        // The feet in contact do not accelerate, and the forces give τ back.
        let jacobians = Solo12.frame_jacobians_world_aligned(&q);
        let drifts = Solo12.frame_acceleration_biases_world_aligned(&q, &v);
        for f in (0..4).filter(|&f| in_contact[f]) {
            for i in 0..3 {
                let acc: f64 = (0..18)
                    .map(|j| jacobians[f][i][j] * got.acceleration[j])
                    .sum();
                let error = (acc + drifts[f][i]).abs() / drifts[f][i].abs().max(1.0);
                assert!(error < 1e-11, "{}", at("a foot in contact accelerates"));
            }
        }
        let back = Solo12.inverse_dynamics_with_forces(&q, &v, &got.acceleration, &got.forces);
        check(&at("rnea(a, λ)"), &back, &tau);
    }
}

/// No foot in contact is `forward_dynamics`, bit for bit; a NaN configuration is refused as
/// `forward_dynamics` refuses it; and the method runs on `f32`.
#[test]
fn contact_dynamics_edges() {
    let samples = samples();
    let s = &samples[3].0;
    let (q, v, tau) = (
        array::<19>(&s["q"]),
        array::<18>(&s["v"]),
        array::<18>(&s["tau"]),
    );
    let free = Solo12
        .contact_dynamics(&q, &v, &tau, &[false; 4])
        .expect("M");
    assert_eq!(free.forces, [[0.0; 3]; 4]);
    let aba = Solo12.forward_dynamics(&q, &v, &tau).expect("M");
    check("no contact", &free.acceleration, &aba);
    let mut nan = q;
    nan[9] = f64::NAN;
    assert_eq!(
        Solo12.contact_dynamics(&nan, &v, &tau, &[true; 4]),
        Err(ContactError::NotPositiveDefinite)
    );
    let (q32, v32, tau32) = (
        q.map(|x| x as f32),
        v.map(|x| x as f32),
        tau.map(|x| x as f32),
    );
    let single = Solo12
        .contact_dynamics(&q32, &v32, &tau32, &[true; 4])
        .expect("independent contacts");
    let double = Solo12
        .contact_dynamics(&q, &v, &tau, &[true; 4])
        .expect("contacts");
    let got: Vec<f64> = single
        .forces
        .iter()
        .flatten()
        .map(|&x| f64::from(x))
        .collect();
    let expected: Vec<f64> = double.forces.iter().flatten().copied().collect();
    assert!(scaled_error(&got, &expected) < 1e-2);
}
