//! The library's front: a motion excited, its torques computed by recursive Newton-Euler
//! (`dynamics_codegen::numeric`, not the regressor), the parameters identified from them and
//! the torques predicted; and its errors, one kind each.

use dynamics_codegen::numeric::Numeric;
use dynamics_codegen::trace::base_parameters::JointColumns;
use dynamics_codegen::{load, Source};
use dynamics_identification::excite::limits::joint_limits;
use dynamics_identification::{excite, identify, predict, Error, Motion, Options};
use dynamics_identification::{Regressor, Samples};
use std::fmt::Write as _;
use std::path::PathBuf;

const PUMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join("dynamics-identification-api");
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir.join(name)
}

fn puma() -> (dynamics_codegen::model::Robot, Regressor) {
    let robot = load(&Source::file(PUMA)).expect("the PUMA 560").robot;
    let columns = robot.joints.iter().map(JointColumns::described).collect();
    let regressor = Regressor::new(&robot, columns, Vec::new()).expect("its regressor");
    (robot, regressor)
}

#[test]
fn exact_torques_give_back_the_described_parameters() {
    let (robot, regressor) = puma();
    let limits = joint_limits(&robot, None, [None; 4]).expect("the default limits");
    let limits = limits.iter().map(|l| l.limits).collect();
    let motion = Motion {
        period: 4.0,
        ..Motion::default()
    };
    let excited = excite(&regressor, limits, &motion, 1, 60, |_| {}).expect("a motion");
    assert!(excited.design.condition.is_finite());
    assert!(excited.design.condition <= excited.design.initial_condition * (1.0 + 1e-12));
    let numeric = Numeric::new(&robot, &[]).expect("numbers only");
    let n = robot.joints.len();
    let mut csv = String::from("t");
    for group in ["q", "qd", "qdd", "tau"] {
        (1..=n).for_each(|i| write!(csv, ",{group}{i}").unwrap());
    }
    csv.push('\n');
    for k in 0..excited.grid.samples() {
        let states = excited.states(k);
        let q: Vec<f64> = states.iter().map(|s| s.q).collect();
        let qd: Vec<f64> = states.iter().map(|s| s.qd).collect();
        let qdd: Vec<f64> = states.iter().map(|s| s.qdd).collect();
        let tau = numeric.inverse_dynamics(&q, &qd, &qdd);
        write!(csv, "{}", excited.time(k)).unwrap();
        for x in q.iter().chain(&qd).chain(&qdd).chain(&tau) {
            write!(csv, ",{x}").unwrap();
        }
        csv.push('\n');
    }
    let path = scratch("exact.csv");
    std::fs::write(&path, csv).expect("the samples written");
    let samples = Samples::open(path.to_str().unwrap(), regressor.columns(), None).expect("read");
    let identified = identify(&regressor, &samples, &Options::default()).expect("an estimate");
    let described = &regressor.model().described;
    let largest = described.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, name) in regressor.names().iter().enumerate() {
        let (estimate, truth) = (identified.estimate.values[k], described[k]);
        assert!(
            (estimate - truth).abs() <= 1e-7 * largest,
            "{name}: {estimate} against {truth}"
        );
    }
    let prediction = predict(&regressor, &samples, &identified.estimate, None).expect("predicted");
    for (error, rms) in prediction.error_rms.iter().zip(&prediction.measured_rms) {
        assert!(*error <= 1e-7 * rms.max(1e-9), "{error} of {rms}");
    }
}

#[test]
fn errors_come_back_as_their_kind() {
    let (_, regressor) = puma();
    // Unfiltered samples are streamed: the file is opened when they are read.
    let samples = Samples::open("no-such-file.csv", regressor.columns(), None).expect("streamed");
    let missing = identify(&regressor, &samples, &Options::default()).err();
    assert!(
        matches!(&missing, Some(Error::Samples(m)) if m.starts_with("no-such-file.csv: ")),
        "{missing:?}"
    );
    let path = scratch("few.csv");
    let header = "t,q1,q2,q3,q4,q5,q6,tau1,tau2,tau3,tau4,tau5,tau6\n";
    let rows: String = (0..20)
        .map(|k| format!("{}{}\n", k, ",0".repeat(12)))
        .collect();
    std::fs::write(&path, format!("{header}{rows}")).unwrap();
    let cutoff = Samples::open(path.to_str().unwrap(), regressor.columns(), Some(0.01));
    assert!(
        matches!(&cutoff, Err(Error::Setting(m)) if m.starts_with("--cutoff 0.01: ")),
        "{:?}",
        cutoff.err()
    );
    let motion = Motion {
        period: 0.1,
        ..Motion::default()
    };
    let few = motion.problem(&regressor, Vec::new()).err();
    assert!(
        matches!(&few, Some(Error::Setting(m)) if m.starts_with("--period × --rate: 10 samples")),
        "{few:?}"
    );
}

/// A robot with mimic joints (the Panda's second finger follows the first: 8 coordinates, 9
/// links) is identified in its coordinates: from noiseless torques of random states, computed
/// by the traced inverse dynamics (checked against Pinocchio in `tests/`), not the regressor,
/// the estimate is its described base parameters.
#[test]
fn a_robot_with_mimic_joints_gives_back_its_base_parameters() {
    use dynamics_codegen::pipeline::State;
    let panda = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf/panda.urdf");
    let mut source = Source::file(panda);
    source.chain.base = Some("panda_link0");
    let robot = load(&source).expect("the Panda").robot;
    assert!(robot.has_mimics());
    let columns = robot.joints.iter().map(JointColumns::described).collect();
    let regressor = Regressor::new(&robot, columns, Vec::new()).expect("its regressor");
    let eq = dynamics_codegen::derive(&robot);
    let n = robot.coordinates().len();
    let mut seed = 7_u64;
    let mut next = |scale: f64| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        #[allow(clippy::cast_precision_loss)]
        let x = (seed >> 11) as f64 / (1_u64 << 53) as f64;
        scale * (2.0 * x - 1.0)
    };
    let mut csv = String::from("t");
    for group in ["q", "qd", "qdd", "tau"] {
        (1..=n).for_each(|i| write!(csv, ",{group}{i}").unwrap());
    }
    csv.push('\n');
    for k in 0..400 {
        let [q, qd, qdd]: [Vec<f64>; 3] =
            [2.0, 1.5, 3.0].map(|scale| (0..n).map(|_| next(scale)).collect());
        let state = State {
            fields: &[],
            q: &q,
            qd: &qd,
            qdd: &qdd,
            tau: &[],
        };
        let tau = eq.evaluate(&state).vector(&eq.tau);
        write!(csv, "{}", 0.01 * f64::from(k)).unwrap();
        for x in q.iter().chain(&qd).chain(&qdd).chain(&tau) {
            write!(csv, ",{x}").unwrap();
        }
        csv.push('\n');
    }
    let path = scratch("mimic.csv");
    std::fs::write(&path, csv).expect("the samples written");
    let samples = Samples::open(path.to_str().unwrap(), regressor.columns(), None).expect("read");
    let identified = identify(&regressor, &samples, &Options::default()).expect("an estimate");
    let described = &regressor.model().described;
    assert_eq!(described.len(), identified.estimate.values.len());
    let largest = described.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, name) in regressor.names().iter().enumerate() {
        let (estimate, truth) = (identified.estimate.values[k], described[k]);
        assert!(
            (estimate - truth).abs() <= 1e-7 * largest,
            "{name}: {estimate} against {truth}"
        );
    }
}
