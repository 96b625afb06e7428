//! Compares every quantity of the crate with the reference data
//! (`tests/data/reference/data/*.json`, computed with Pinocchio and cross-checked with
//! the Robotics Toolbox) for all robots and all 20 samples.

use crate::common::{json_files, load_robot, matrix4_error, matrix_error, scaled_error};
use dynamics_reference::nalgebra::{DMatrix, Matrix4};
use dynamics_reference::{Convention, Robot};
use serde::Deserialize;

/// Tolerance on `max|a − b| / max(1, max|b|)`.
const TOLERANCE: f64 = 1e-10;

#[derive(Deserialize)]
struct DataFile {
    robot: String,
    n: usize,
    description: Robot,
    samples: Vec<Sample>,
}

#[derive(Deserialize)]
#[allow(non_snake_case)]
struct Sample {
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
    M: Vec<Vec<f64>>,
    h: Vec<f64>,
    g: Vec<f64>,
    C: Vec<Vec<f64>>,
    kinetic_energy: f64,
    potential_energy: f64,
    ee_pose: Vec<Vec<f64>>,
    jacobian: Vec<Vec<f64>>,
}

fn to_matrix(rows: &[Vec<f64>]) -> DMatrix<f64> {
    let ncols = rows.first().map_or(0, Vec::len);
    assert!(rows.iter().all(|r| r.len() == ncols), "ragged matrix");
    DMatrix::from_fn(rows.len(), ncols, |r, c| rows[r][c])
}

fn to_matrix4(rows: &[Vec<f64>]) -> Matrix4<f64> {
    assert_eq!(rows.len(), 4);
    Matrix4::from_fn(|r, c| rows[r][c])
}

const QUANTITIES: [&str; 10] = [
    "tau",
    "M",
    "C",
    "h",
    "g",
    "KE",
    "PE",
    "ee_pose",
    "jacobian",
    "C qd vs sum",
];

/// Worst scaled error of each quantity over the samples of one data file.
fn check_file(data: &DataFile) -> [f64; 10] {
    let robot = &data.description;
    assert_eq!(robot.dof(), data.n, "{}: n", data.robot);
    let mut worst = [0.0_f64; 10];
    for s in &data.samples {
        let (q, qd, qdd) = (&s.q[..], &s.qd[..], &s.qdd[..]);
        let coriolis = robot.coriolis_matrix(q, qd);
        let coriolis_sum = robot.coriolis_torques(q, qd);
        let gravity = robot.gravity_torques(q);
        let h = &coriolis_sum + &gravity;
        let errors = [
            scaled_error(robot.inverse_dynamics(q, qd, qdd).as_slice(), &s.tau),
            matrix_error(&robot.mass_matrix(q), &to_matrix(&s.M)),
            matrix_error(&coriolis, &to_matrix(&s.C)),
            scaled_error(h.as_slice(), &s.h),
            scaled_error(gravity.as_slice(), &s.g),
            scaled_error(&[robot.kinetic_energy(q, qd)], &[s.kinetic_energy]),
            scaled_error(&[robot.potential_energy(q)], &[s.potential_energy]),
            matrix4_error(&robot.forward_kinematics(q), &to_matrix4(&s.ee_pose)),
            matrix_error(&robot.jacobian(q), &to_matrix(&s.jacobian)),
            scaled_error(
                (&coriolis * dynamics_reference::nalgebra::DVector::from_column_slice(qd))
                    .as_slice(),
                coriolis_sum.as_slice(),
            ),
        ];
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    worst
}

#[test]
fn matches_reference_data_for_all_robots() {
    let files = json_files("data");
    assert_eq!(
        files.len(),
        8,
        "expected the 8 reference data files, got {files:?}"
    );
    let mut failures = Vec::new();
    let mut saw_modified = false;
    eprintln!(
        "worst scaled error max|a-b|/max(1,max|b|) over 20 samples, per robot (tolerance {TOLERANCE:e}):"
    );
    for path in &files {
        let text = std::fs::read_to_string(path).expect("readable data file");
        let data: DataFile = serde_json::from_str(&text)
            .unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()));
        assert_eq!(data.samples.len(), 20, "{}: sample count", data.robot);
        saw_modified |= data.description.convention == Convention::Modified;

        // The stand-alone robot file describes the same robot.
        let robot_file = load_robot(&data.robot);
        assert_eq!(robot_file.dof(), data.n);
        assert_eq!(robot_file.convention, data.description.convention);

        let worst = check_file(&data);
        let overall = worst.iter().copied().fold(0.0_f64, f64::max);
        let detail: Vec<String> = QUANTITIES
            .iter()
            .zip(worst)
            .map(|(name, e)| format!("{name} {e:.1e}"))
            .collect();
        eprintln!(
            "  {:<11} worst {overall:.2e}  ({})",
            data.robot,
            detail.join(", ")
        );
        if overall.is_nan() || overall > TOLERANCE {
            failures.push(format!("{}: {overall:e}", data.robot));
        }
    }
    assert!(saw_modified, "no modified-convention robot in the data");
    assert!(failures.is_empty(), "robots over tolerance: {failures:?}");
}

/// A 7-joint arm in the modified convention, the Franka Emika Panda (`tests/data/panda/`,
/// Pinocchio 4.1.0, checked against the URDF its parameters come from).
#[test]
fn matches_the_panda_data() {
    let path = crate::common::reference_dir().join("../panda/data.json");
    let text = std::fs::read_to_string(&path).expect("tests/data/panda/data.json");
    let data: DataFile = serde_json::from_str(&text).expect("panda data");
    assert_eq!((data.n, data.samples.len()), (7, 20));
    assert_eq!(data.description.convention, Convention::Modified);
    let worst = check_file(&data);
    for (name, e) in QUANTITIES.iter().zip(worst) {
        assert!(e <= TOLERANCE, "panda: {name} off by {e:e}");
    }
    eprintln!(
        "panda: worst scaled error {:.1e}",
        worst.iter().copied().fold(0.0, f64::max)
    );
}
