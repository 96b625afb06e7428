//! 6-D (surface) contacts beside 3-D (point) ones, `FloatingContacts::constrained_dynamics`,
//! against Pinocchio 4.1's `constraintDynamics` with CONTACT_6D and CONTACT_3D in
//! LOCAL_WORLD_ALIGNED (`<robot>_surface_contacts.json`, by `make.py`'s `surface`, which checks
//! Pinocchio against numpy's solve of the full KKT system): the Unitree G1 on its two flat feet,
//! one flat and one a point, and so on, and Solo 12 with one foot flat and the others points, at
//! the states of their data files, to 1e-12 scaled; the frames held do not move
//! (`J a + γ = 0`, a surface's `γ` its spatial acceleration); point contacts alone are
//! `contact_dynamics`.

use super::floating_base::{array, reference, Solo12, G1, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::{Contact, FloatingContacts};

/// The contacts of a sample, `"surface"`, `"point"` or `"none"` per frame.
pub(crate) fn contacts<const F: usize>(x: &serde_json::Value) -> [Contact; F] {
    let kinds: Vec<Contact> = x
        .as_array()
        .expect("a kind per frame")
        .iter()
        .map(|k| match k.as_str().expect("a kind") {
            "surface" => Contact::Surface,
            "point" => Contact::Point,
            "none" => Contact::Free,
            other => panic!("unknown contact `{other}`"),
        })
        .collect();
    kinds.try_into().expect("a kind per frame")
}

/// Every sample of `<name>_surface_contacts.json`: `a` and the wrenches to `tolerance`, the
/// frames held still, and `τ` given back by inverse dynamics with the wrenches.
fn against_pinocchio<R, const Q: usize, const V: usize, const F: usize>(
    robot: &R,
    name: &str,
    frame_names: [&str; F],
    tolerance: f64,
) -> f64
where
    R: FloatingContacts<Q, V, F>,
{
    let data = reference(&format!("{name}_surface_contacts"));
    let frames: Vec<&str> = data["frames"]
        .as_array()
        .expect("frames")
        .iter()
        .map(|f| f.as_str().expect("a name"))
        .collect();
    assert_eq!(frames, frame_names.to_vec(), "{name}: the frames");
    let states = reference(name)["samples"].clone();
    let states = states.as_array().expect("samples");
    let samples = data["samples"].as_array().expect("samples");
    assert_eq!(states.len(), samples.len());
    let mut worst: f64 = 0.0;
    for (k, (s, c)) in states.iter().zip(samples).enumerate() {
        let (q, v, tau) = (
            array::<Q>(&s["q"]),
            array::<V>(&s["v"]),
            array::<V>(&s["tau"]),
        );
        let held: [Contact; F] = contacts(&c["contacts"]);
        let at = |what: &str| format!("{name} sample {k}, {held:?}: {what}");
        let got = robot
            .constrained_dynamics(&q, &v, &tau, &held)
            .expect("independent contacts");
        let expected: Vec<f64> = super::floating_base::flat(&c["wrenches"]);
        for (what, got, expected) in [
            (
                "ddq",
                got.acceleration.to_vec(),
                super::floating_base::flat(&c["a_contact"]),
            ),
            ("wrenches", got.wrenches.concat(), expected),
        ] {
            let error = scaled_error(&got, &expected);
            worst = worst.max(error);
            assert!(error < tolerance, "{} off by {error:e}", at(what));
        }
        // The frames held do not move: `J a + γ = 0`, a surface's γ its spatial acceleration.
        let jacobians = robot.frame_jacobians_world_aligned(&q);
        let classical = robot.frame_acceleration_biases_world_aligned(&q, &v);
        for (f, contact) in held.iter().enumerate() {
            let rows = match contact {
                Contact::Free => 0,
                Contact::Point => 3,
                Contact::Surface => 6,
            };
            let dot = |row: &[f64; V], x: &[f64; V]| -> f64 {
                row.iter().zip(x).map(|(a, b)| a * b).sum()
            };
            let twist: [f64; 6] = std::array::from_fn(|r| dot(&jacobians[f][r], &v));
            for r in 0..rows {
                let mut gamma = classical[f][r];
                if *contact == Contact::Surface && r < 3 {
                    let (o, w) = (&twist[..3], &twist[3..]);
                    gamma -= w[(r + 1) % 3] * o[(r + 2) % 3] - w[(r + 2) % 3] * o[(r + 1) % 3];
                }
                let acc = dot(&jacobians[f][r], &got.acceleration) + gamma;
                assert!(
                    acc.abs() / gamma.abs().max(1.0) < 1e-9,
                    "{}",
                    at("a frame held moves")
                );
            }
        }
        // The wrenches give τ back.
        let back = robot.inverse_dynamics_with_wrenches(&q, &v, &got.acceleration, &got.wrenches);
        let error = scaled_error(&back, &tau);
        assert!(error < 1e-9, "{} off by {error:e}", at("rnea(a, wrenches)"));
    }
    worst
}

#[test]
fn solo12_one_foot_flat_against_pinocchio() {
    let worst = against_pinocchio(&Solo12, "solo12", Solo12::FRAME_NAMES, TOLERANCE);
    assert!(worst < TOLERANCE);
}

/// The G1's M has a condition number up to 3.5e5 (`floating_derivatives.rs`), and Pinocchio's
/// own result is off numpy's KKT solve by up to 9.2e-13 scaled on these samples (`kkt_gap`):
/// the largest error here, 8.8e-13, is within 1e-12 all the same.
#[test]
fn g1_on_flat_feet_against_pinocchio() {
    let gap = reference("g1_29dof_surface_contacts")["kkt_gap"]
        .as_f64()
        .expect("the gap");
    let worst = against_pinocchio(&G1, "g1_29dof", G1::FRAME_NAMES, TOLERANCE);
    eprintln!("G1 surface contacts: worst {worst:e}, Pinocchio against numpy {gap:e}");
}

/// Points alone are `contact_dynamics` (computed in closed form, another way), to 1e-12.
#[test]
fn points_alone_are_contact_dynamics() {
    let s = &reference("solo12")["samples"][5];
    let (q, v, tau) = (
        array::<19>(&s["q"]),
        array::<18>(&s["v"]),
        array::<18>(&s["tau"]),
    );
    for mask in [[true; 4], [true, false, false, true], [false; 4]] {
        let points = mask.map(|held| if held { Contact::Point } else { Contact::Free });
        let got = Solo12
            .constrained_dynamics(&q, &v, &tau, &points)
            .expect("held");
        let expected = Solo12.contact_dynamics(&q, &v, &tau, &mask).expect("held");
        let error = scaled_error(&got.acceleration, &expected.acceleration);
        assert!(error < TOLERANCE, "{mask:?}: a off by {error:e}");
        let forces: Vec<f64> = got.wrenches.iter().flat_map(|w| w[..3].to_vec()).collect();
        let error = scaled_error(&forces, &expected.forces.concat());
        assert!(error < TOLERANCE, "{mask:?}: forces off by {error:e}");
        assert!(got.wrenches.iter().all(|w| w[3..] == [0.0; 3]));
    }
}
