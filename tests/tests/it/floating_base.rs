//! Robots on a free-flying base, derived from their URDFs with `base = floating`: the quadrupeds
//! Solo 12 and ANYmal B and the humanoid Unitree G1 against Pinocchio 4.1's free flyer
//! (`tests/data/floating/*.json`, by `make.py`): M, h, τ and g at random states with random
//! unit quaternions, to 1e-12 scaled by the largest element of each.

use dynamics_reference::scaled_error;
use dynamics_runtime::FloatingDynamics;

/// The bar: 1e-12, scaled by max(1, the largest element); the floating tests share it.
pub(crate) const TOLERANCE: f64 = 1e-12;

/// Solo 12, its root link the floating body, its four feet (the leaf links) the frames of its
/// kinematics: the one derive of it that the floating tests share (each derive costs the
/// tests' build).
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating,
    contacts = true
)]
pub(crate) struct Solo12;

/// The same robot with its floating body named, and without `contacts = true`: its contact
/// terms are computed at run time.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating("base_link")
)]
pub(crate) struct Solo12Named;

/// ANYmal B (`anymal_b_simple_description`), a quadruped of 12 joints.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/anymal_b.urdf",
    base = floating,
    contacts = true
)]
pub(crate) struct AnymalB;

/// The Unitree G1 humanoid (`g1_description`, 29 joints, no hands).
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(urdf = "../robots/urdf/floating/g1_29dof.urdf", base = floating)]
pub(crate) struct G1;

/// The numbers of `x`, a list or a list of lists, flattened.
pub(crate) fn flat(x: &serde_json::Value) -> Vec<f64> {
    match x.as_array() {
        Some(items) => items.iter().flat_map(flat).collect(),
        None => vec![x.as_f64().expect("a number")],
    }
}

pub(crate) fn numbers(x: &serde_json::Value) -> Vec<f64> {
    x.as_array()
        .expect("a list")
        .iter()
        .map(|e| e.as_f64().expect("a number"))
        .collect()
}

pub(crate) fn array<const N: usize>(x: &serde_json::Value) -> [f64; N] {
    numbers(x).try_into().expect("the length")
}

/// The reference data of `robot` (`tests/data/floating/ROBOT.json`).
pub(crate) fn reference(robot: &str) -> serde_json::Value {
    let path = format!("{}/data/floating/{robot}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the data");
    serde_json::from_str(&text).expect("JSON")
}

/// M, h, τ and g of `robot` at every sample of its data file `name`, to [`TOLERANCE`].
pub(crate) fn check_against_pinocchio<R: FloatingDynamics<Q, V>, const Q: usize, const V: usize>(
    robot: &R,
    name: &str,
) {
    let data = reference(name);
    assert_eq!(
        (data["nq"].as_u64(), data["nv"].as_u64()),
        (Some(Q as u64), Some(V as u64))
    );
    let samples = data["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    for (k, s) in samples.iter().enumerate() {
        let (q, v, a) = (
            array::<Q>(&s["q"]),
            array::<V>(&s["v"]),
            array::<V>(&s["a"]),
        );
        let m: Vec<f64> = robot.mass_matrix(&q).iter().flatten().copied().collect();
        let expected_m: Vec<f64> = s["M"]
            .as_array()
            .expect("rows")
            .iter()
            .flat_map(numbers)
            .collect();
        for (what, got, expected) in [
            ("M", m, expected_m),
            ("h", robot.bias_forces(&q, &v).to_vec(), numbers(&s["h"])),
            (
                "tau",
                robot.inverse_dynamics(&q, &v, &a).to_vec(),
                numbers(&s["tau"]),
            ),
            (
                "g",
                robot.generalized_gravity(&q).to_vec(),
                numbers(&s["g"]),
            ),
        ] {
            let error = scaled_error(&got, &expected);
            assert!(
                error < TOLERANCE,
                "{name} sample {k}: {what} off by {error:e}"
            );
        }
    }
}

#[test]
fn solo12_against_pinocchio() {
    assert_eq!((Solo12::NQ, Solo12::NV), (19, 18));
    check_against_pinocchio(&Solo12, "solo12");
    for s in reference("solo12")["samples"].as_array().expect("samples") {
        let q = array::<19>(&s["q"]);
        assert_eq!(
            Solo12.mass_matrix(&q),
            Solo12Named.mass_matrix(&q),
            "the root link named is the root link"
        );
    }
}

/// ANYmal B: its legs are LF, RF, LH, RH in the file (Pinocchio's parser orders them by name;
/// the data are in the file's order), the trunk carries ten fixed links.
#[test]
fn anymal_b_against_pinocchio() {
    assert_eq!((AnymalB::NQ, AnymalB::NV), (19, 18));
    check_against_pinocchio(&AnymalB, "anymal_b");
}

/// The Unitree G1 humanoid, 29 joints: two legs of six, a waist of three, two arms of seven.
#[test]
fn g1_against_pinocchio() {
    assert_eq!((G1::NQ, G1::NV), (36, 35));
    check_against_pinocchio(&G1, "g1_29dof");
}

/// In `f32` too, at the precision of `f32`.
#[test]
fn solo12_in_f32() {
    let data = reference("solo12");
    let s = &data["samples"][3];
    let (q, v, a) = (
        array::<19>(&s["q"]),
        array::<18>(&s["v"]),
        array::<18>(&s["a"]),
    );
    let single = |x: &[f64]| x.iter().map(|&e| e as f32).collect::<Vec<f32>>();
    let (q32, v32, a32) = (single(&q), single(&v), single(&a));
    let tau = Solo12.inverse_dynamics(
        &q32.try_into().expect("19"),
        &v32.try_into().expect("18"),
        &a32.try_into().expect("18"),
    );
    let got: Vec<f64> = tau.iter().map(|&x| f64::from(x)).collect();
    let error = scaled_error(&got, &numbers(&s["tau"]));
    assert!(error < 1e-4, "τ in f32 off by {error:e}");
}

/// `mass_matrix_into` is the by-value `mass_matrix` bit for bit, into a matrix of zeros or the
/// previous state's M, and leaves the blocks between two legs (exact zeros: no leg moves
/// another) as the caller's matrix has them.
#[test]
fn solo12_mass_matrix_into() {
    // Joints 3 per leg, after the base's six coordinates.
    let leg = |k: usize| (k >= 6).then(|| (k - 6) / 3);
    let mut previous = [[0.0; 18]; 18];
    for s in reference("solo12")["samples"].as_array().expect("samples") {
        let q = array::<19>(&s["q"]);
        let want = Solo12.mass_matrix(&q);
        let mut nan = [[f64::NAN; 18]; 18];
        Solo12.mass_matrix_into(&q, &mut nan);
        for (i, row) in nan.iter().enumerate() {
            for (j, &got) in row.iter().enumerate() {
                let between_legs = matches!((leg(i), leg(j)), (Some(a), Some(b)) if a != b);
                if between_legs {
                    assert!(got.is_nan(), "M[{i}][{j}] between legs written");
                } else {
                    let left = got.is_nan() && want[i][j] == 0.0;
                    assert!(got.to_bits() == want[i][j].to_bits() || left, "M[{i}][{j}]");
                }
            }
        }
        let mut zeros = [[0.0; 18]; 18];
        Solo12.mass_matrix_into(&q, &mut zeros);
        Solo12.mass_matrix_into(&q, &mut previous);
        let bits = |m: [[f64; 18]; 18]| m.map(|row| row.map(f64::to_bits));
        assert_eq!(bits(zeros), bits(want));
        assert_eq!(bits(previous), bits(want));
    }
}
