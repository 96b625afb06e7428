//! Shared pieces of the benchmarks of the generated dynamics (see `bench/README.md`).
//!
//! * The four 6-joint reference robots of `tests/data/reference/robots/`, each derived with
//!   `#[derive(Dynamics)]` from its JSON description: [`Puma560`], [`Stanford`], [`Ur5`] and
//!   [`Random5`]; the 7-joint [`Panda`] of `tests/data/panda/`; and [`Ur5Dh`], the UR5 of
//!   `robots/urdf/ur5.urdf` written as a D-H table (`robots/ur5_urdf_dh.toml`, data in
//!   `tests/data/urdf/`), the twin the URDF robot is compared with, beside [`Ur5Urdf`],
//!   derived from the URDF itself.
//! * Their 20 reference samples (`q`, `qd`, `qdd` and the expected `tau`, computed with
//!   Pinocchio 4.1.0), read at run time by [`samples`].
//! * The two other implementations the generated code is compared with, built from the same
//!   descriptions: the plain numeric recursive Newton-Euler / composite-rigid-body of
//!   `dynamics-codegen` ([`numeric`]) and the book's O(n⁴) Lagrangian method of
//!   `dynamics-reference` ([`book`]).
//!
//! Used by the `timings` binary (the numbers compared with Pinocchio) and by the criterion
//! benchmark `benches/dynamics.rs`.

use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
use dynamics_codegen::{Equations, FamilySet, Loaded, Numeric, Source};
use dynamics_runtime::Dynamics;

/// Number of joints of the four 6-joint reference robots.
pub const DOF: usize = 6;

/// Names of the benchmarked robots, in output order: the four 6-joint reference robots, whose
/// description and data are `tests/data/reference/{robots,data}/<name>.json`, `panda`, whose
/// are `tests/data/panda/{robot,data}.json`, `ur5_dh`, whose data file
/// `tests/data/urdf/ur5_dh.json` holds its description, and `ur5_urdf`, the same robot from its
/// URDF, whose data are `tests/data/urdf/ur5.json`.
pub const ROBOTS: [&str; 7] = [
    "puma560", "stanford", "ur5", "random5", "panda", "ur5_dh", "ur5_urdf",
];

/// The PUMA 560 (Corke's Robotics Toolbox parameters, motor inertia and friction dropped): RRRRRR.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
// Links 1 and 3 as published break the triangle inequality of principal moments.
#[dynamics(
    file = "../tests/data/reference/robots/puma560.json",
    check_inertia = false,
    derivatives = true,
    regressor = true,
    base_parameters = true,
    // `simplification("puma560")` restates it: about 1 % of the peak torques over the
    // envelope of docs/design/simplified.md's figures.
    simplify(
        tolerance = [0.22, 0.6, 0.13, 0.0004, 0.0005, 0.00001],
        q_min = -2.5,
        q_max = 2.0,
        qd_max = 2,
        qdd_max = 5,
    )
)]
pub struct Puma560;

/// The Stanford arm (Robotics Toolbox parameters): RRPRRR.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
// Link 5 as published breaks the triangle inequality of principal moments.
#[dynamics(
    file = "../tests/data/reference/robots/stanford.json",
    check_inertia = false,
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Stanford;

/// The UR5 (Robotics Toolbox parameters, point masses): RRRRRR.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    file = "../tests/data/reference/robots/ur5.json",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Ur5;

/// A seeded random robot with general inertial parameters: PRPRRR.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    file = "../tests/data/reference/robots/random5.json",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Random5;

/// The Franka Emika Panda arm (modified D-H, inertias from its URDF): RRRRRRR.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    file = "../tests/data/panda/robot.json",
    derivatives = true,
    regressor = true,
    base_parameters = true,
    // `simplification("panda")` restates it: 1 % of the rated torques (the URDF's `effort`)
    // over the URDF's ranges and speeds (robots/urdf/panda.urdf), |q̈| ≤ 5.
    simplify(
        rated = [87, 87, 87, 87, 12, 12, 12],
        tolerance_percent = 1,
        q_min = [-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973],
        q_max = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973],
        qd_max = [2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61],
    )
)]
pub struct Panda;

/// The UR5 of `robots/urdf/ur5.urdf` as a modified D-H table, its link inertials re-expressed in
/// the D-H frames (`tests/data/urdf/twins.py`): RRRRRR. Not the Robotics Toolbox's [`Ur5`].
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    file = "../robots/ur5_urdf_dh.toml",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Ur5Dh;

/// The UR5 derived from its URDF (`robots/urdf/ur5.urdf`, base_link to tool0): the robot of
/// [`Ur5Dh`], lowered to its own D-H table by the URDF front end.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/ur5.urdf",
    base = "base_link",
    tip = "tool0",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Ur5Urdf;

/// One reference sample of an `N`-joint robot: a state and the torques Pinocchio computed for it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<const N: usize = DOF> {
    /// Joint positions.
    pub q: [f64; N],
    /// Joint velocities.
    pub qd: [f64; N],
    /// Joint accelerations.
    pub qdd: [f64; N],
    /// Expected inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)`.
    pub tau: [f64; N],
}

const DATA_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data");

/// The text of `tests/data/<file>`.
fn read(file: &str) -> String {
    let path = format!("{DATA_DIR}/{file}");
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
}

/// The data file of `robot` in `tests/data/`.
fn data_file(robot: &str) -> String {
    match robot {
        "panda" => "panda/data.json".into(),
        "ur5_dh" => "urdf/ur5_dh.json".into(),
        "ur5_urdf" => "urdf/ur5.json".into(),
        "baxter_no_mimic" | "allegro_right_hand" => format!("trees/{robot}.json"),
        _ => format!("reference/data/{robot}.json"),
    }
}

fn vector<const N: usize>(v: &serde_json::Value, what: &str) -> [f64; N] {
    let a = v
        .as_array()
        .unwrap_or_else(|| panic!("{what} is not an array"));
    assert_eq!(a.len(), N, "{what} has {} entries, not {N}", a.len());
    core::array::from_fn(|i| {
        a[i].as_f64()
            .unwrap_or_else(|| panic!("{what}[{i}] is not a number"))
    })
}

/// The 20 reference samples of `robot` (one of [`ROBOTS`], or a tree: `baxter_no_mimic`,
/// `allegro_right_hand`), read from its data file.
///
/// # Panics
/// If the file is missing or malformed, or the robot has not `N` joints.
#[must_use]
pub fn samples<const N: usize>(robot: &str) -> Vec<Sample<N>> {
    let data: serde_json::Value = serde_json::from_str(&read(&data_file(robot)))
        .unwrap_or_else(|e| panic!("data of {robot}: {e}"));
    let samples = data["samples"]
        .as_array()
        .unwrap_or_else(|| panic!("data of {robot} has no samples"));
    samples
        .iter()
        .map(|s| Sample {
            q: vector(&s["q"], "q"),
            qd: vector(&s["qd"], "qd"),
            qdd: vector(&s["qdd"], "qdd"),
            tau: vector(&s["tau"], "tau"),
        })
        .collect()
}

/// The JSON description of `robot`: the file its struct is derived from, or for the UR5's twin
/// (and the URDF UR5, the same robot) as the twin's data file describes it.
///
/// # Panics
/// If the file is missing.
#[must_use]
pub fn description(robot: &str) -> String {
    match robot {
        "panda" => read("panda/robot.json"),
        "ur5_dh" | "ur5_urdf" => {
            let data: serde_json::Value = serde_json::from_str(&read(&data_file("ur5_dh")))
                .unwrap_or_else(|e| panic!("data of ur5_dh: {e}"));
            data["description"].to_string()
        }
        _ => read(&format!("reference/robots/{robot}.json")),
    }
}

/// `robot` evaluated by the plain numeric recursive Newton-Euler (`inverse_dynamics`) and
/// composite-rigid-body (`mass_matrix`) algorithms of `dynamics-codegen`, with loops over the
/// joints at run time.
///
/// # Panics
/// If the description is missing or invalid.
#[must_use]
pub fn numeric(robot: &str) -> Numeric {
    // The reference robots name no struct fields: every parameter is a number.
    Numeric::new(&loaded(robot).robot, &[])
        .unwrap_or_else(|e| panic!("{robot} needs field {:?}", e.0))
}

/// `robot`'s description read through the generator's front door, as the derives of this
/// crate read it (`check_inertia = false`: some links as published break the triangle
/// inequality of principal moments).
///
/// # Panics
/// If the description is missing or invalid.
#[must_use]
pub fn loaded(robot: &str) -> Loaded {
    let text = description(robot);
    let path = format!("{robot}.json");
    let source = Source {
        path: &path,
        text: Some(&text),
        check_inertia: false,
        ..Source::default()
    };
    dynamics_codegen::load(&source).unwrap_or_else(|problems| {
        let lines: Vec<String> = problems.iter().map(ToString::to_string).collect();
        panic!("description of {robot}: {}", lines.join("; "))
    })
}

/// `robot` evaluated by the book's method (Niku, ch. 6: Lagrangian with 4×4 matrices,
/// O(n⁴)), as implemented by `dynamics-reference`.
///
/// # Panics
/// If the description is missing or invalid.
#[must_use]
pub fn book(robot: &str) -> dynamics_reference::Robot {
    dynamics_reference::Robot::from_json(&description(robot))
        .unwrap_or_else(|e| panic!("description of {robot}: {e}"))
}

pub use dynamics_reference::scaled_error;

mod floating;
mod trees;
pub use floating::{
    floating_contact_samples, floating_derivative_samples, floating_regressor_samples,
    floating_samples, AnymalB, FloatingDerivativeSample, FloatingSample, Solo12, FLOATING, G1,
};
pub use trees::{AllegroHand, BaxterFreeFingers};

/// The robots with simplified models (`simplify(...)` in their derives).
pub const SIMPLIFIED: [&str; 2] = ["puma560", "panda"];

/// The request of the `simplify(...)` of `robot`'s derive (one of [`SIMPLIFIED`]), restated
/// for its bounds ([`simplified`]); bench/ffi's tests check that the two give the same model.
#[must_use]
pub fn simplification(robot: &str) -> Option<Simplification> {
    let (tolerance, joints): (Vec<f64>, Vec<JointEnvelope>) = match robot {
        "puma560" => {
            let joint = JointEnvelope {
                lower: -2.5,
                upper: 2.0,
                speed: 2.0,
                acceleration: 5.0,
            };
            let tolerance = vec![0.22, 0.6, 0.13, 0.0004, 0.0005, 0.00001];
            (tolerance, vec![joint; 6])
        }
        "panda" => {
            let lower = [
                -2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973,
            ];
            let upper = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973];
            let speed = [2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61];
            let rated = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0];
            let joints = (0..7).map(|i| JointEnvelope {
                lower: lower[i],
                upper: upper[i],
                speed: speed[i],
                acceleration: 5.0,
            });
            (rated.iter().map(|r| r * 0.01).collect(), joints.collect())
        }
        _ => return None,
    };
    Some(Simplification {
        tolerance,
        envelope: Envelope { joints },
    })
}

/// The equations of `robot` (one of [`SIMPLIFIED`]) with its simplified models, pruned from its
/// description for [`simplification`] as the derive prunes them: their bounds and envelope.
///
/// # Panics
/// If the description is missing or invalid, or the request refused.
#[must_use]
pub fn simplified(robot: &str) -> Option<Equations> {
    let request = simplification(robot)?;
    let eq = loaded(robot)
        .equations(FamilySet::default(), Some(&request))
        .unwrap_or_else(|e| panic!("simplified {robot}: {e}"));
    Some(eq)
}
