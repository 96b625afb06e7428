//! The book's method on kinematic trees against Pinocchio (`tests/data/trees/*.json`, the files
//! with `pinocchio_model`: Baxter without mimic, the Allegro hand, the Panda with free
//! fingers): the robot read URDF style from the record of Pinocchio's model, every sample's τ,
//! M, C, h, g, both energies and each tip's pose and Jacobian.

use std::collections::BTreeMap;
use std::path::PathBuf;

use dynamics_reference::nalgebra::{DMatrix, DVector};
use dynamics_reference::{Convention, Robot};
use dynamics_test_support::relative_error;
use serde::Deserialize;

use crate::common::scaled_error;

/// Tolerance on the scaled error `max|a − b| / max(1, max|b|)`, and on the hand's relative one
/// `max|a − b| / max|b|` (its M is ~1e-3 kg m², its τ ~0.05 N m: the scaled measure would be an
/// absolute one), each over all samples of a quantity.
const TOLERANCE: f64 = 1e-12;

#[derive(Deserialize)]
struct Tip {
    pose: Vec<Vec<f64>>,
    jacobian: Vec<Vec<f64>>,
}

#[derive(Deserialize)]
#[allow(non_snake_case)]
struct Sample {
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
    M: Vec<Vec<f64>>,
    C: Vec<Vec<f64>>,
    h: Vec<f64>,
    g: Vec<f64>,
    kinetic_energy: f64,
    potential_energy: f64,
    tips: BTreeMap<String, Tip>,
}

#[derive(Deserialize)]
struct DataFile {
    robot: String,
    n: usize,
    parents: Vec<Option<usize>>,
    pinocchio_model: Option<serde_json::Value>,
    samples: Vec<Sample>,
}

/// The tree data files, sorted.
fn tree_files() -> Vec<PathBuf> {
    let dir = crate::common::reference_dir().join("../trees");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        // The mimic regressor's data, in a format of its own (`mimic_regressor.py`).
        .filter(|p| !p.to_string_lossy().ends_with("_regressor.json"))
        .collect();
    files.sort();
    files
}

fn flat(rows: &[Vec<f64>]) -> Vec<f64> {
    rows.iter().flatten().copied().collect()
}

/// Row-major entries of a matrix.
fn rows(m: &DMatrix<f64>) -> Vec<f64> {
    m.transpose().as_slice().to_vec()
}

/// Every quantity of every sample, ours then Pinocchio's, concatenated over the samples.
#[derive(Default)]
struct Pairs(BTreeMap<String, (Vec<f64>, Vec<f64>)>);

impl Pairs {
    fn add(&mut self, name: &str, ours: &[f64], theirs: &[f64]) {
        assert_eq!(ours.len(), theirs.len(), "{name}: length");
        let entry = self.0.entry(name.to_owned()).or_default();
        entry.0.extend_from_slice(ours);
        entry.1.extend_from_slice(theirs);
    }
}

/// Our quantities and Pinocchio's over every sample of a file.
fn compare(robot: &Robot, frames: &[dynamics_reference::PinocchioFrame], data: &DataFile) -> Pairs {
    let mut pairs = Pairs::default();
    for s in &data.samples {
        let (q, qd, qdd) = (&s.q[..], &s.qd[..], &s.qdd[..]);
        let coriolis = robot.coriolis_matrix(q, qd);
        let gravity = robot.gravity_torques(q);
        let h = &coriolis * DVector::from_column_slice(qd) + &gravity;
        pairs.add("tau", robot.inverse_dynamics(q, qd, qdd).as_slice(), &s.tau);
        pairs.add("M", &rows(&robot.mass_matrix(q)), &flat(&s.M));
        pairs.add("C", &rows(&coriolis), &flat(&s.C));
        pairs.add("h", h.as_slice(), &s.h);
        pairs.add("g", gravity.as_slice(), &s.g);
        pairs.add("KE", &[robot.kinetic_energy(q, qd)], &[s.kinetic_energy]);
        pairs.add("PE", &[robot.potential_energy(q)], &[s.potential_energy]);
        for f in frames {
            let tip = &s.tips[&f.name];
            let pose = robot.frame(q, f.link) * f.offset;
            let pose_rows: Vec<f64> = (0..4)
                .flat_map(|r| (0..4).map(move |c| (r, c)))
                .map(|rc| pose[rc])
                .collect();
            pairs.add("tip pose", &pose_rows, &flat(&tip.pose));
            let jacobian = robot.frame_jacobian(q, f.link, &f.offset);
            pairs.add("tip jacobian", &rows(&jacobian), &flat(&tip.jacobian));
        }
    }
    pairs
}

#[test]
fn matches_pinocchio_on_every_tree_with_a_model() {
    let mut robots = Vec::new();
    let mut failures = Vec::new();
    eprintln!("worst error over 20 samples (scaled; the hand relative), tolerance {TOLERANCE:e}:");
    for path in tree_files() {
        let text = std::fs::read_to_string(&path).expect("readable data file");
        let data: DataFile = serde_json::from_str(&text)
            .unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()));
        let Some(model) = &data.pinocchio_model else {
            continue;
        };
        let (robot, frames) = Robot::from_pinocchio_model(&data.robot, &model.to_string())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(robot.convention, Convention::Urdf);
        assert_eq!(robot.dof(), data.n, "{}: n", data.robot);
        let parents: Vec<Option<usize>> = (0..robot.dof()).map(|i| robot.antecedent(i)).collect();
        assert_eq!(parents, data.parents, "{}: antecedents", data.robot);
        assert_eq!(data.samples.len(), 20, "{}: samples", data.robot);
        assert!(
            !frames.is_empty()
                && frames
                    .iter()
                    .all(|f| data.samples[0].tips.contains_key(&f.name))
        );
        let relative = data.robot.starts_with("allegro");
        let mut detail = Vec::new();
        for (name, (ours, theirs)) in &compare(&robot, &frames, &data).0 {
            let e = if relative {
                relative_error(ours, theirs)
            } else {
                scaled_error(ours, theirs)
            };
            detail.push(format!("{name} {e:.1e}"));
            if e.is_nan() || e > TOLERANCE {
                failures.push(format!("{}: {name} off by {e:e}", data.robot));
            }
        }
        eprintln!("  {:<24} {}", data.robot, detail.join(", "));
        robots.push(data.robot);
    }
    assert_eq!(
        robots,
        [
            "allegro_right_hand",
            "baxter_no_mimic",
            "panda_fingers_no_mimic"
        ],
        "the trees with a Pinocchio model"
    );
    assert!(failures.is_empty(), "{failures:#?}");
}
