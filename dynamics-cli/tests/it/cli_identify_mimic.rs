//! `dynamics identify` on a robot with a mimic joint (L = 5 joints, N = 4 coordinates): the
//! synthetic arm with a joint after its second that follows it (`q₃ = −0.7 q₂ + 0.3`, with its
//! own rotor, friction and spring), so that the prismatic wrist is the fourth coordinate and
//! the fifth joint. The measured torques are those of the same arm with every joint free
//! (`Numeric::inverse_dynamics`, not the reduction under test) at `q_full = S q + o`, projected
//! by hand: `τ = Sᵀ τ_full` (row 2 gains −0.7 τ₃). Noise-free, the base parameters found
//! reproduce them and predict another trajectory's to the serial tests' tolerance; the report
//! and figure give each coordinate its own joint's number and unit.

use crate::synthetic::{dynamics, fourier, json, scratch, write_csv, State};
use dynamics_codegen::numeric::Numeric;

const K: f64 = -0.7;
const O: f64 = 0.3;

/// The arm, its third joint following the second where `mimic` (else free).
fn text(mimic: bool) -> String {
    let rule = if mimic {
        "mimic = { joint = 2, multiplier = -0.7, offset = 0.3 }\n"
    } else {
        ""
    };
    format!(
        r#"name = "arm5"
gravity = [0, 0, -9.81]

[[joints]]
type = "revolute"
d = 0.4
alpha = "90 deg"
mass = 3
com = [0, -0.1, 0.02]
inertia = [0.05, 0.04, 0.03, 0.001, 0, 0.002]
actuator_inertia = 0.2
friction_viscous = 0.8
friction_coulomb = 1.2

[[joints]]
type = "revolute"
a = 0.5
mass = 4
com = [-0.25, 0.01, 0.03]
inertia = [0.02, 0.09, 0.08, 0.003, -0.002, 0.001]
actuator_inertia = 0.15
friction_viscous = 0.5
friction_coulomb = 0.9

[[joints]]
type = "revolute"
{rule}a = 0.2
alpha = "30 deg"
mass = 1.0
com = [-0.1, 0.02, 0.01]
inertia = [0.004, 0.01, 0.009, 0, 0.0005, 0]
actuator_inertia = 0.05
friction_viscous = 0.4
spring_stiffness = 6
spring_rest = 0.1

[[joints]]
type = "revolute"
a = 0.35
alpha = "-90 deg"
mass = 2.5
com = [-0.15, 0, 0.05]
inertia = [0.01, 0.03, 0.025, 0, 0.001, 0]
actuator_inertia = 0.08
friction_viscous = 0.3
friction_coulomb = 0.4

[[joints]]
type = "prismatic"
theta = "90 deg"
mass = 1.2
com = [0.01, 0.02, -0.05]
inertia = [0.004, 0.005, 0.003, 0, 0, 0]
actuator_inertia = 0.5
friction_viscous = 2.0
friction_coulomb = 1.5
"#
    )
}

/// `x` of the coordinates as the five joints' (`offset` for positions).
fn full(x: &[f64], offset: f64) -> Vec<f64> {
    vec![x[0], x[1], K * x[1] + offset, x[2], x[3]]
}

/// The torques of the coordinates at `states`, from the free arm projected by hand, with the
/// mimic joint's spring taken out (the description's springs are known: `identify` subtracts
/// them from the measured torques).
fn torques(states: &[State]) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let free = dynamics_codegen::front::load("arm5.toml", &text(false))
        .expect("the free arm reads")
        .robot;
    let numeric = Numeric::new(&free, &[]).expect("no fields");
    let mut measured = Vec::new();
    let mut springless = Vec::new();
    for s in states {
        let q = full(&s.q, O);
        let t = numeric.inverse_dynamics(&q, &full(&s.qd, 0.0), &full(&s.qdd, 0.0));
        let tau = vec![t[0], t[1] + K * t[2], t[3], t[4]];
        let mut rigid = tau.clone();
        rigid[1] -= K * 6.0 * (q[2] - 0.1);
        measured.push(tau);
        springless.push(rigid);
    }
    (measured, springless)
}

#[test]
fn a_mimic_robot_is_identified_from_its_coordinates() {
    let path = scratch("arm5.toml");
    std::fs::write(&path, text(true)).expect("write robot");
    let robot = path.to_str().expect("a path");
    let states = fourier(4, 1500, 100.0, 0.7, &[]);
    let (tau, _) = torques(&states);
    let csv = write_csv("mimic.csv", &states, &tau, true);
    let other = fourier(4, 200, 50.0, 2.3, &[]);
    let (other_tau, truth) = torques(&other);
    let other_csv = write_csv("mimic_other.csv", &other, &other_tau, true);
    let svg = scratch("mimic.svg");
    let svg = svg.to_str().expect("a path");
    // The mimic link's inertia moves only with q2 (its angle −0.7 q2 + 0.3): on this motion
    // YZR3's column is within 1e-4 of the others' span (the default --tolerance would leave it
    // out, residual 2e-5 N m), not within 1e-8.
    let args = [
        "identify",
        robot,
        "--csv",
        &csv,
        "--json",
        "--validate",
        &other_csv,
        "--plot",
        svg,
        "--tolerance",
        "1e-8",
    ];
    let report = json(&dynamics(&args));
    assert_eq!(report["springs_subtracted"].as_bool(), Some(true));
    let scale = tau.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let joints = report["joints"].as_array().expect("joints");
    let units: Vec<&str> = joints.iter().map(|j| j["unit"].as_str().unwrap()).collect();
    assert_eq!(units, ["N m", "N m", "N m", "N"]);
    let numbers: Vec<u64> = joints
        .iter()
        .map(|j| j["joint"].as_u64().unwrap())
        .collect();
    assert_eq!(numbers, [1, 2, 4, 5]);
    for joint in joints {
        let rms = joint["residual_rms"].as_f64().unwrap();
        assert!(rms < 1e-9 * scale, "{joint}");
    }
    let validation = report["validation"]["joints"].as_array().expect("joints");
    for (i, joint) in validation.iter().enumerate() {
        let rms = (truth.iter().map(|t| t[i] * t[i]).sum::<f64>() / 200.0).sqrt();
        let reported = joint["rms"].as_f64().unwrap();
        assert!((reported - rms).abs() < 1e-12 * rms, "{joint}: {rms}");
        let error = joint["error_rms"].as_f64().unwrap();
        assert!(error < 1e-9 * scale, "{joint}");
    }
    // The text and the figure: the fourth coordinate is joint 5, a prismatic joint.
    let text_args = ["identify", robot, "--csv", &csv, "--tolerance", "1e-8"];
    let out = dynamics(&text_args);
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row = table
        .lines()
        .rev()
        .find(|l| l.trim_start().starts_with("5 "))
        .unwrap_or_else(|| panic!("joint 5's row: {table}"));
    assert!(row.trim_end().ends_with(" N"), "{row}");
    assert!(
        !table.lines().any(|l| l.trim_start().starts_with("3 ")),
        "{table}"
    );
    let figure = std::fs::read_to_string(svg).expect("the figure is written");
    assert!(figure.contains("joint 5: τ4 (N)"), "{figure}");
}

/// `dynamics excite` on the same arm: a trajectory of its four coordinates (not its five
/// joints), each row of the report its joint's number and unit.
#[test]
fn a_mimic_robot_is_excited_in_its_coordinates() {
    let path = scratch("arm5_excite.toml");
    std::fs::write(&path, text(true)).expect("write robot");
    let csv = scratch("arm5_excite.csv");
    let args = [
        "excite",
        path.to_str().expect("a path"),
        "--evaluations",
        "20",
        "--json",
        "--csv",
        csv.to_str().expect("a path"),
    ];
    let report = json(&dynamics(&args));
    let joints = report["joints"].as_array().expect("joints");
    let rows: Vec<(u64, &str)> = joints
        .iter()
        .map(|j| (j["joint"].as_u64().unwrap(), j["unit"].as_str().unwrap()))
        .collect();
    assert_eq!(rows, [(1, "rad"), (2, "rad"), (4, "rad"), (5, "m")]);
    let trajectory = std::fs::read_to_string(&csv).expect("the trajectory");
    let header = trajectory.lines().next().expect("a header");
    assert_eq!(header, "t,q1,q2,q3,q4,qd1,qd2,qd3,qd4,qdd1,qdd2,qdd3,qdd4");
}

/// A mimic joint's Coulomb friction is not grouped into its joint's base parameter: on the
/// coordinate it follows, its torque `k sign(k q̇₂)` is `|k| sign(q̇₂)`, `|k|` = 0.7 times the
/// column of that joint's own Coulomb friction, so `identify` names it not identified, a
/// multiple of `FC2` (docs/identification.md).
#[test]
fn a_mimic_joints_coulomb_friction_is_a_multiple_of_its_joints() {
    let viscous = "friction_viscous = 0.4\n";
    let described = text(true).replacen(viscous, &format!("{viscous}friction_coulomb = 0.6\n"), 1);
    assert_ne!(described, text(true), "the third joint's friction");
    let path = scratch("arm5_coulomb.toml");
    std::fs::write(&path, described).expect("write robot");
    // The torques of the arm without it: its column, not its value, is what is checked.
    let states = fourier(4, 600, 100.0, 0.7, &[]);
    let (tau, _) = torques(&states);
    let csv = write_csv("mimic_coulomb.csv", &states, &tau, true);
    let robot = path.to_str().expect("a path");
    let out = dynamics(&["identify", robot, "--csv", &csv, "--tolerance", "1e-8"]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = report
        .lines()
        .find(|l| l.trim_start().starts_with("FC3: "))
        .unwrap_or_else(|| panic!("FC3 not identified: {report}"));
    assert!(line.contains("its column is +7.0000e-1 FC2 "), "{line}");
}
