//! Contacts at the feet of a robot on a free-flying base (`FloatingContacts`): Solo 12 against
//! Pinocchio 4.1 (`tests/data/floating/solo12_contacts.json`, by `make.py`'s `contacts`, at the
//! states of `solo12.json`): `rnea` and `aba` with external wrenches and point forces at the
//! feet, and `constraintDynamics` with CONTACT_3D at the feet in contact (a set per sample), to
//! 1e-12 scaled by the largest element of each; and the constraint itself, `J a + J̇ v = 0` at
//! the feet in contact, and `τ` given back by inverse dynamics with the contact forces.

use super::floating_base::{array, numbers, reference, AnymalB, Solo12, Solo12Named, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{
    ContactDynamics, ContactError, ContactTerms, FloatingContactTerms, FloatingContacts,
    FloatingDynamics, FloatingKinematics,
};

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

/// The generated contact terms against the products of the generated (and checked) `M⁻¹`,
/// `h`, `J` and `J̇ v`: `a₀ = M⁻¹ (τ − h)`, `J a₀ + γ`, `M⁻¹ Jᵀ` and `J M⁻¹ Jᵀ`.
#[test]
fn closed_form_contact_terms() {
    // With `contacts = true` the closed form; without, the trait's run-time form: the same
    // terms.
    let forms = [
        <Solo12 as FloatingContactTerms<19, 18, 4>>::CLOSED_FORM,
        <Solo12Named as FloatingContactTerms<19, 18, 4>>::CLOSED_FORM,
    ];
    assert_eq!(forms, [true, false]);
    for (k, (s, _)) in samples().iter().enumerate() {
        let (q, v, tau) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["tau"]),
        );
        let at = |what: &str| format!("sample {k}: {what}");
        let terms = Solo12.contact_terms(&q, &v, &tau).expect("M");
        let at_run_time = Solo12Named.contact_terms(&q, &v, &tau).expect("M");
        let flat = |t: &ContactTerms<f64, 18, 4>| -> Vec<f64> {
            let mut all = t.free_acceleration.to_vec();
            all.extend(t.frame_accelerations.iter().flatten());
            all.extend(t.minv_jt.iter().flatten().flatten());
            all.extend(t.delassus.iter().flatten().flatten().flatten());
            all
        };
        check(&at("at run time"), &flat(&at_run_time), &flat(&terms));
        let minv = Solo12.mass_matrix_inverse(&q).expect("M");
        let free = Solo12.forward_dynamics(&q, &v, &tau).expect("M");
        check(&at("a0"), &terms.free_acceleration, &free);
        let jacobians = Solo12.frame_jacobians_world_aligned(&q);
        let drifts = Solo12.frame_acceleration_biases_world_aligned(&q, &v);
        let dot =
            |a: &[f64; 18], b: &[f64; 18]| -> f64 { a.iter().zip(b).map(|(x, y)| x * y).sum() };
        let minv_jt: Vec<[f64; 18]> = (0..12)
            .map(|r| std::array::from_fn(|i| dot(&minv[i], &jacobians[r / 3][r % 3])))
            .collect();
        let got: Vec<f64> = terms.minv_jt.iter().flatten().flatten().copied().collect();
        check(&at("M⁻¹ Jᵀ"), &got, &minv_jt.concat());
        let delassus: Vec<f64> = (0..144)
            .map(|e| dot(&jacobians[e / 36][e / 12 % 3], &minv_jt[e % 12]))
            .collect();
        let got: Vec<f64> = terms
            .delassus
            .iter()
            .flatten()
            .flatten()
            .flatten()
            .copied()
            .collect();
        check(&at("J M⁻¹ Jᵀ"), &got, &delassus);
        let accelerations: Vec<f64> = (0..12)
            .map(|r| dot(&jacobians[r / 3][r % 3], &free) + drifts[r / 3][r % 3])
            .collect();
        let got: Vec<f64> = terms
            .frame_accelerations
            .iter()
            .flatten()
            .copied()
            .collect();
        check(&at("J a0 + γ"), &got, &accelerations);
    }
}

/// Two frames held at one point, exactly: the block of `Λ⁻¹` `[[1, 1], [1, 1]]` (each entry
/// a 3 × 3 identity) has a zero pivot in exact arithmetic, as in `f64`. One frame alone, or
/// none, is solved: `λ = −(J a₀ + γ)`, `a = a₀ + M⁻¹ Jᵀ λ`.
#[test]
fn dependent_contacts() {
    let identity: [[f64; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j))));
    let terms = ContactTerms::<f64, 2, 2> {
        free_acceleration: [1.0, 2.0],
        frame_accelerations: [[1.0, 2.0, 3.0], [1.0, 2.0, 3.0]],
        minv_jt: [[[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]; 2],
        delassus: std::array::from_fn(|_| std::array::from_fn(|i| [identity[i]; 2])),
    };
    assert_eq!(
        terms.solve(&[true; 2]),
        Err(ContactError::DependentContacts)
    );
    assert_eq!(
        terms.solve(&[false, true]),
        Ok(ContactDynamics {
            acceleration: [1.0 - 1.0 - 3.0, 2.0 - 2.0 - 3.0],
            forces: [[0.0; 3], [-1.0, -2.0, -3.0]],
        })
    );
    assert_eq!(
        terms.solve(&[false; 2]).map(|d| d.acceleration),
        Ok([1.0, 2.0])
    );
}

/// Every foot held, on Solo 12 and ANYmal B, against Pinocchio's `constraintDynamics`
/// (`<robot>_contact_fd.json`): the feet the same frames in the same order.
fn every_foot_held<R: FloatingContacts<19, 18, 4>>(robot: &R, name: &str, frames: [&str; 4]) {
    let data = reference(&format!("{name}_contact_fd"));
    let names: Vec<&str> = data["frames"]
        .as_array()
        .expect("frames")
        .iter()
        .map(|f| f["name"].as_str().expect("a name"))
        .collect();
    assert_eq!(names, frames, "{name}");
    let states = reference(name)["samples"]
        .as_array()
        .expect("samples")
        .clone();
    let samples = data["samples"].as_array().expect("samples");
    assert_eq!(states.len(), samples.len());
    for (k, (s, c)) in states.iter().zip(samples).enumerate() {
        let (q, v, tau) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["tau"]),
        );
        let got = robot
            .contact_dynamics(&q, &v, &tau, &[true; 4])
            .expect("independent contacts");
        let at = |what: &str| format!("{name} sample {k}: {what}");
        check(&at("ddq"), &got.acceleration, &numbers(&c["a_contact"]));
        let expected: Vec<f64> = rows::<3, 4>(&c["lambda"])
            .iter()
            .flatten()
            .copied()
            .collect();
        let forces: Vec<f64> = got.forces.iter().flatten().copied().collect();
        check(&at("lambda"), &forces, &expected);
    }
}

#[test]
fn every_foot_held_against_pinocchio() {
    every_foot_held(&Solo12, "solo12", Solo12::FRAME_NAMES);
    every_foot_held(&Solo12Named, "solo12", Solo12Named::FRAME_NAMES);
    every_foot_held(&AnymalB, "anymal_b", AnymalB::FRAME_NAMES);
}
