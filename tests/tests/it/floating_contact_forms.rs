//! The contacts' nalgebra and batch forms (`FloatingContactsNalgebra`,
//! `FloatingContactsBatch`, `ContactTermsNalgebra::solve`) on Solo 12: each against its array
//! form (the nalgebra forms bit for bit: a copy around the call; the batch forms bit for bit
//! against one call per state, in both layouts, a group of states holding the same feet in
//! lanes and one whose feet differ state by state one state at a time) and against Pinocchio
//! 4.1's data (`solo12_contacts.json`, `solo12_surface_contacts.json`) to 1e-12 scaled.

use super::floating_base::{array, numbers, reference, Solo12, TOLERANCE};
use dynamics_reference::scaled_error;
use dynamics_runtime::batch::FloatingContactsBatch;
use dynamics_runtime::nalgebra::{ContactTermsNalgebra, FloatingContactsNalgebra};
use dynamics_runtime::{
    ConstrainedDynamics, Contact, ContactDynamics, ContactError, ContactTerms,
    FloatingContactTerms, FloatingContacts, NotPositiveDefinite,
};
use nalgebra::{SVector, Vector3};

/// A state of `solo12.json` with its contact data: q, v, a, tau, the wrenches, the forces, the
/// feet in contact.
struct Sample {
    q: [f64; 19],
    v: [f64; 18],
    a: [f64; 18],
    tau: [f64; 18],
    wrenches: [[f64; 6]; 4],
    forces: [[f64; 3]; 4],
    in_contact: [bool; 4],
    contact: serde_json::Value,
}

fn rows<const N: usize, const F: usize>(x: &serde_json::Value) -> [[f64; N]; F] {
    let rows: Vec<[f64; N]> = x.as_array().expect("rows").iter().map(array).collect();
    rows.try_into().expect("a row per frame")
}

fn samples() -> Vec<Sample> {
    let states = reference("solo12")["samples"].clone();
    let contacts = reference("solo12_contacts")["samples"].clone();
    let (states, contacts) = (
        states.as_array().expect("samples"),
        contacts.as_array().expect("samples"),
    );
    assert_eq!(states.len(), contacts.len());
    states
        .iter()
        .zip(contacts)
        .map(|(s, c)| Sample {
            q: array(&s["q"]),
            v: array(&s["v"]),
            a: array(&s["a"]),
            tau: array(&s["tau"]),
            wrenches: rows(&c["wrenches"]),
            forces: rows(&c["forces"]),
            in_contact: c["in_contact"]
                .as_array()
                .expect("a mask")
                .iter()
                .map(|b| b.as_bool().expect("a bool"))
                .collect::<Vec<_>>()
                .try_into()
                .expect("a flag per foot"),
            contact: c.clone(),
        })
        .collect()
}

fn check(what: &str, got: &[f64], expected: &[f64]) {
    assert_eq!(got.len(), expected.len(), "{what}: the length");
    let error = scaled_error(got, expected);
    assert!(error < TOLERANCE, "{what} off by {error:e}");
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|x| x.to_bits()).collect()
}

fn flat_terms(t: &ContactTerms<f64, 18, 4>) -> Vec<f64> {
    let mut all = t.free_acceleration.to_vec();
    all.extend(t.frame_accelerations.iter().flatten());
    all.extend(t.minv_jt.iter().flatten().flatten());
    all.extend(t.delassus.iter().flatten().flatten().flatten());
    all
}

fn flat_contact(d: &ContactDynamics<f64, 18, 4>) -> Vec<f64> {
    let mut all = d.acceleration.to_vec();
    all.extend(d.forces.iter().flatten());
    all
}

fn flat_constrained(d: &ConstrainedDynamics<f64, 18, 4>) -> Vec<f64> {
    let mut all = d.acceleration.to_vec();
    all.extend(d.wrenches.iter().flatten());
    all
}

#[test]
fn nalgebra_forms_are_the_array_forms() {
    for (k, s) in samples().iter().enumerate() {
        nalgebra_wrenches_and_forces(k, s);
        nalgebra_contacts(k, s);
    }
}

/// The nalgebra forms with wrenches and forces, sample `k`.
fn nalgebra_wrenches_and_forces(k: usize, s: &Sample) {
    let at = |what: &str| format!("sample {k}: {what}");
    let (q, v, a, tau) = (
        SVector::from(s.q),
        SVector::from(s.v),
        SVector::from(s.a),
        SVector::from(s.tau),
    );
    let wrenches = s.wrenches.map(SVector::from);
    let forces = s.forces.map(Vector3::from);
    let got = Solo12.inverse_dynamics_with_wrenches_na(&q, &v, &a, &wrenches);
    let array_form = Solo12.inverse_dynamics_with_wrenches(&s.q, &s.v, &s.a, &s.wrenches);
    assert_eq!(
        bits(got.as_slice()),
        bits(&array_form),
        "{}",
        at("rnea, wrenches")
    );
    check(
        &at("rnea, wrenches"),
        got.as_slice(),
        &numbers(&s.contact["tau_wrenches"]),
    );
    let got = Solo12.inverse_dynamics_with_forces_na(&q, &v, &a, &forces);
    check(
        &at("rnea, forces"),
        got.as_slice(),
        &numbers(&s.contact["tau_forces"]),
    );
    let got = Solo12
        .forward_dynamics_with_wrenches_na(&q, &v, &tau, &wrenches)
        .expect("M");
    check(
        &at("aba, wrenches"),
        got.as_slice(),
        &numbers(&s.contact["a_wrenches"]),
    );
    let got = Solo12
        .forward_dynamics_with_forces_na(&q, &v, &tau, &forces)
        .expect("M");
    let array_form = Solo12
        .forward_dynamics_with_forces(&s.q, &s.v, &s.tau, &s.forces)
        .expect("M");
    assert_eq!(
        bits(got.as_slice()),
        bits(&array_form),
        "{}",
        at("aba, forces")
    );
    check(
        &at("aba, forces"),
        got.as_slice(),
        &numbers(&s.contact["a_forces"]),
    );
}

/// The nalgebra forms of the held contacts and of the terms, sample `k`.
fn nalgebra_contacts(k: usize, s: &Sample) {
    let at = |what: &str| format!("sample {k}: {what}");
    let (q, v, tau) = (SVector::from(s.q), SVector::from(s.v), SVector::from(s.tau));
    let got = Solo12
        .contact_dynamics_na(&q, &v, &tau, &s.in_contact)
        .expect("independent contacts");
    let array_form = Solo12
        .contact_dynamics(&s.q, &s.v, &s.tau, &s.in_contact)
        .expect("independent contacts");
    let mut flat = got.acceleration.as_slice().to_vec();
    flat.extend(got.forces.iter().flat_map(|f| f.iter().copied()));
    assert_eq!(
        bits(&flat),
        bits(&flat_contact(&array_form)),
        "{}",
        at("contacts")
    );
    check(
        &at("ddq"),
        got.acceleration.as_slice(),
        &numbers(&s.contact["a_contact"]),
    );
    // The terms' blocks, and their solve, are the array terms' and theirs.
    let terms: ContactTermsNalgebra<f64, 18, 4> = Solo12.contact_terms_na(&q, &v, &tau).expect("M");
    let array_terms = Solo12.contact_terms(&s.q, &s.v, &s.tau).expect("M");
    assert_eq!(
        bits(&flat_terms(&ContactTerms::from(&terms))),
        bits(&flat_terms(&array_terms)),
        "{}",
        at("terms")
    );
    assert_eq!(
        terms.delassus[1][2][(0, 1)],
        array_terms.delassus[1][0][2][1]
    );
    assert_eq!(terms.minv_jt[3][(7, 2)], array_terms.minv_jt[3][2][7]);
    assert_eq!(terms.solve(&s.in_contact), Ok(got));
}

/// The states of the samples, input by input.
struct Columns {
    samples: Vec<Sample>,
    q: Vec<[f64; 19]>,
    v: Vec<[f64; 18]>,
    a: Vec<[f64; 18]>,
    tau: Vec<[f64; 18]>,
    wrenches: Vec<[[f64; 6]; 4]>,
    forces: Vec<[[f64; 3]; 4]>,
}

/// The batch forms, state by state, on the 12 samples (groups of four whose feet differ, and
/// the last group one state short) and on the same states all with every foot held (groups
/// in lanes).
#[test]
fn batch_forms_are_one_call_per_state() {
    let samples = samples();
    let c = Columns {
        q: samples.iter().map(|s| s.q).collect(),
        v: samples.iter().map(|s| s.v).collect(),
        a: samples.iter().map(|s| s.a).collect(),
        tau: samples.iter().map(|s| s.tau).collect(),
        wrenches: samples.iter().map(|s| s.wrenches).collect(),
        forces: samples.iter().map(|s| s.forces).collect(),
        samples,
    };
    for len in [0, 1, 3, 4, 5, 11, 12] {
        inverse_batches(&c, len);
        solved_batches(&c, len);
    }
    let Columns {
        samples, q, v, tau, ..
    } = &c;
    // The 12 samples' own feet against Pinocchio.
    let masks: Vec<[bool; 4]> = samples.iter().map(|s| s.in_contact).collect();
    let mut out = vec![Err(ContactError::DependentContacts); samples.len()];
    Solo12.contact_dynamics_batch(&q[..], &v[..], &tau[..], &masks[..], &mut out[..]);
    for (got, s) in out.iter().zip(samples.iter()) {
        let got = got.expect("held");
        check(
            "batch ddq",
            &got.acceleration,
            &numbers(&s.contact["a_contact"]),
        );
    }
}

/// The inverse dynamics' batch forms, the first `len` states.
fn inverse_batches(c: &Columns, len: usize) {
    let Columns {
        samples,
        q,
        v,
        a,
        wrenches,
        forces,
        ..
    } = c;
    let mut out = vec![[0.0; 18]; len];
    Solo12.inverse_dynamics_with_wrenches_batch(
        &q[..len],
        &v[..len],
        &a[..len],
        &wrenches[..len],
        &mut out[..],
    );
    for (k, got) in out.iter().enumerate() {
        let one = Solo12.inverse_dynamics_with_wrenches(&q[k], &v[k], &a[k], &wrenches[k]);
        assert_eq!(bits(got), bits(&one), "rnea, wrenches: state {k} of {len}");
        check(
            "rnea, wrenches",
            got,
            &numbers(&samples[k].contact["tau_wrenches"]),
        );
    }
    // One slice per frame: the same.
    let per_frame: [Vec<[f64; 3]>; 4] =
        std::array::from_fn(|f| forces[..len].iter().map(|x| x[f]).collect());
    let per_frame: [&[[f64; 3]]; 4] = std::array::from_fn(|f| &per_frame[f][..]);
    let mut out = vec![[0.0; 18]; len];
    Solo12.inverse_dynamics_with_forces_batch(
        &q[..len],
        &v[..len],
        &a[..len],
        &per_frame,
        &mut out[..],
    );
    for (k, got) in out.iter().enumerate() {
        let one = Solo12.inverse_dynamics_with_forces(&q[k], &v[k], &a[k], &forces[k]);
        assert_eq!(bits(got), bits(&one), "rnea, forces: state {k} of {len}");
    }
}

/// The batch forms that solve, the first `len` states.
fn solved_batches(c: &Columns, len: usize) {
    let Columns {
        samples,
        q,
        v,
        tau,
        wrenches,
        forces,
        ..
    } = c;
    let mut out = vec![Err(NotPositiveDefinite); len];
    Solo12.forward_dynamics_with_wrenches_batch(
        &q[..len],
        &v[..len],
        &tau[..len],
        &wrenches[..len],
        &mut out[..],
    );
    for (k, got) in out.iter().enumerate() {
        let one = Solo12.forward_dynamics_with_wrenches(&q[k], &v[k], &tau[k], &wrenches[k]);
        assert_eq!(
            bits(&got.expect("M")),
            bits(&one.expect("M")),
            "aba, wrenches: state {k}"
        );
    }
    let mut out = vec![Err(NotPositiveDefinite); len];
    Solo12.forward_dynamics_with_forces_batch(
        &q[..len],
        &v[..len],
        &tau[..len],
        &forces[..len],
        &mut out[..],
    );
    for (k, got) in out.iter().enumerate() {
        let one = Solo12.forward_dynamics_with_forces(&q[k], &v[k], &tau[k], &forces[k]);
        assert_eq!(
            bits(&got.expect("M")),
            bits(&one.expect("M")),
            "aba, forces: state {k}"
        );
    }
    let mut out = vec![Err(NotPositiveDefinite); len];
    Solo12.contact_terms_batch(&q[..len], &v[..len], &tau[..len], &mut out[..]);
    for (k, got) in out.iter().enumerate() {
        let one = Solo12.contact_terms(&q[k], &v[k], &tau[k]).expect("M");
        assert_eq!(
            bits(&flat_terms(&got.expect("M"))),
            bits(&flat_terms(&one)),
            "terms: state {k}"
        );
    }
    for masks in [
        samples.iter().map(|s| s.in_contact).collect::<Vec<_>>(),
        vec![[true; 4]; samples.len()],
    ] {
        let mut out = vec![Err(ContactError::DependentContacts); len];
        Solo12.contact_dynamics_batch(
            &q[..len],
            &v[..len],
            &tau[..len],
            &masks[..len],
            &mut out[..],
        );
        for (k, got) in out.iter().enumerate() {
            let one = Solo12
                .contact_dynamics(&q[k], &v[k], &tau[k], &masks[k])
                .expect("held");
            let got = got.expect("held");
            assert_eq!(
                bits(&flat_contact(&got)),
                bits(&flat_contact(&one)),
                "contacts: state {k} of {len}"
            );
        }
    }
}

/// `constrained_dynamics`' forms on Solo 12's samples of `solo12_surface_contacts.json` (one
/// foot flat, others points): nalgebra and batch against the array form, bit for bit, the
/// array form against Pinocchio.
#[test]
fn constrained_dynamics_forms() {
    let data = reference("solo12_surface_contacts");
    let states = reference("solo12")["samples"].clone();
    let states = states.as_array().expect("samples");
    let samples = data["samples"].as_array().expect("samples");
    let contacts: Vec<[Contact; 4]> = samples
        .iter()
        .map(|s| super::floating_surface_contacts::contacts(&s["contacts"]))
        .collect();
    let q: Vec<[f64; 19]> = states.iter().map(|s| array(&s["q"])).collect();
    let v: Vec<[f64; 18]> = states.iter().map(|s| array(&s["v"])).collect();
    let tau: Vec<[f64; 18]> = states.iter().map(|s| array(&s["tau"])).collect();
    let mut out = vec![Err(ContactError::DependentContacts); q.len()];
    Solo12.constrained_dynamics_batch(&q[..], &v[..], &tau[..], &contacts[..], &mut out[..]);
    let same = vec![contacts[0]; q.len()];
    let mut lanes = vec![Err(ContactError::DependentContacts); q.len()];
    Solo12.constrained_dynamics_batch(&q[..], &v[..], &tau[..], &same[..], &mut lanes[..]);
    for k in 0..q.len() {
        let one = Solo12
            .constrained_dynamics(&q[k], &v[k], &tau[k], &contacts[k])
            .expect("independent");
        let got = out[k].expect("independent");
        assert_eq!(
            bits(&flat_constrained(&got)),
            bits(&flat_constrained(&one)),
            "state {k}"
        );
        let flat_one = Solo12
            .constrained_dynamics(&q[k], &v[k], &tau[k], &same[k])
            .map(|d| bits(&flat_constrained(&d)));
        assert_eq!(
            lanes[k].map(|d| bits(&flat_constrained(&d))),
            flat_one,
            "in lanes: state {k}"
        );
        let na = Solo12
            .constrained_dynamics_na(
                &SVector::from(q[k]),
                &SVector::from(v[k]),
                &SVector::from(tau[k]),
                &contacts[k],
            )
            .expect("independent");
        assert_eq!(na.acceleration.as_slice(), &one.acceleration[..]);
        let wrenches: Vec<f64> = na.wrenches.iter().flat_map(|w| w.iter().copied()).collect();
        assert_eq!(wrenches, one.wrenches.concat());
        check(
            &format!("sample {k}: ddq"),
            &one.acceleration,
            &numbers(&samples[k]["a_contact"]),
        );
    }
}
