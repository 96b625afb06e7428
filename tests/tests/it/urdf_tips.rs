//! The kinematics of every tip (`TipKinematics`) of robots that branch, derived from their
//! URDFs, against Pinocchio 4.1.0 (`tests/data/trees/<robot>.json`: each tip's pose and
//! Jacobian, `LOCAL_WORLD_ALIGNED`) and the book's method (`dynamics-reference`, the robot read
//! from the file's record of Pinocchio's model):
//!
//! * the poses and the Jacobians in base axes against Pinocchio's; in the tip's axes against
//!   Pinocchio's carried by the tip's rotation (`LOCAL`: `[Rᵀ v; Rᵀ ω]`);
//! * `J̇ q̇` against central differences of the reference's Jacobian along the motion;
//! * the torques of a wrench at each tip against `Σ_t J_tᵀ F_t` of Pinocchio's Jacobians.
//!
//! The Allegro hand names its fingertips (`tips = [..]`, links fixed to the last finger
//! links); the Panda with free fingers takes its leaves (the two finger links). The hand's
//! quantities are compared relative to their size (see `urdf_trees`).

use dynamics_reference::nalgebra::{DMatrix, DVector};
use dynamics_reference::{PinocchioFrame, Robot};
use dynamics_runtime::{Dynamics, Pose, TipKinematics};
use dynamics_tests::reference::{samples, vector};
// The same derive as `urdf_trees.rs`' (its attribute names no tips: the leaves, both fingers).
use crate::urdf_trees::PandaFreeFingers;
use serde_json::Value;

/// The hand's published inertias break the triangle inequality (Pinocchio takes them as given).
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/trees/allegro_right_hand.urdf",
    base = "palm_link",
    tips = ["link_3.0_tip", "link_7.0_tip", "link_11.0_tip", "link_15.0_tip"],
    check_inertia = false
)]
struct AllegroTips;

/// The Panda with its URDF's `<mimic>`: the second finger follows the first (8 coordinates).
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/panda.urdf",
    base = "panda_link0",
    tips = ["panda_leftfinger", "panda_rightfinger"]
)]
struct PandaMimicTips;

/// `max|got − want| / max(1, max|want|)`, or relative to `max|want|` (`relative`).
fn error(got: &[f64], want: &[f64], relative: bool) -> f64 {
    let largest = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let worst = got
        .iter()
        .zip(want)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert_eq!(got.len(), want.len());
    if relative && largest > 0.0 {
        worst / largest
    } else {
        worst / largest.max(1.0)
    }
}

/// The rows of a JSON matrix.
fn rows(v: &Value) -> Vec<Vec<f64>> {
    let rows = v.as_array().expect("rows");
    rows.iter()
        .map(|r| {
            r.as_array()
                .expect("row")
                .iter()
                .map(|x| x.as_f64().expect("number"))
                .collect()
        })
        .collect()
}

/// A Jacobian `[v; ω]` in base axes carried into axes turned by `r`: `[Rᵀ v; Rᵀ ω]`.
fn in_axes(j: &[Vec<f64>], r: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let turn = |block: usize, i: usize, c: usize| (0..3).map(|k| r[k][i] * j[block + k][c]).sum();
    (0..6)
        .map(|row| {
            (0..j[0].len())
                .map(|c| turn(row / 3 * 3, row % 3, c))
                .collect()
        })
        .collect()
}

/// The reference robot and its frames, from the data file's record of Pinocchio's model.
fn reference(file: &str) -> (Robot, Vec<PinocchioFrame>) {
    let path = format!("{}/data/trees/{file}", env!("CARGO_MANIFEST_DIR"));
    let data: Value =
        serde_json::from_str(&std::fs::read_to_string(&path).expect("data")).expect("JSON");
    let model = data["pinocchio_model"].to_string();
    Robot::from_pinocchio_model(file, &model).expect("the record of Pinocchio's model")
}

/// `J̇ q̇` of `frame` by central differences of the reference's Jacobian along `q + t q̇`,
/// Richardson-extrapolated (steps h and h/2), so that its error is far below the tolerance.
fn bias_by_differences(robot: &Robot, frame: &PinocchioFrame, q: &[f64], qd: &[f64]) -> Vec<f64> {
    let at = |t: f64| {
        let q: Vec<f64> = q.iter().zip(qd).map(|(q, v)| q + t * v).collect();
        robot.frame_jacobian(&q, frame.link, &frame.offset)
    };
    let rate = |h: f64| (at(h) - at(-h)) / (2.0 * h);
    let (h1, h2) = (rate(1e-3), rate(5e-4));
    let rate: DMatrix<f64> = (h2 * 4.0 - h1) / 3.0;
    (rate * DVector::from_column_slice(qd))
        .iter()
        .copied()
        .collect()
}

/// A pose's rows `[R | p]`, one after the other.
fn pose_rows(pose: &Pose<f64>) -> Vec<f64> {
    (0..3)
        .flat_map(|i| {
            [
                pose.rotation[i][0],
                pose.rotation[i][1],
                pose.rotation[i][2],
                pose.position[i],
            ]
        })
        .collect()
}

/// A spatial vector `[v; ω]` in base axes in axes turned by `r`: `[Rᵀ v; Rᵀ ω]`.
fn turned(x: &[f64], r: &[Vec<f64>]) -> Vec<f64> {
    (0..6)
        .map(|row| (0..3).map(|m| r[m][row % 3] * x[row / 3 * 3 + m]).sum())
        .collect()
}

/// Every tip of `robot` against every sample of `file`, within `tolerance` (the differences'
/// `J̇ q̇` within `difference_tolerance`); returns the worst error of each check.
fn check<R, const N: usize, const TIPS: usize>(
    robot: &R,
    tip_names: [&str; TIPS],
    file: &str,
    relative: bool,
    tolerance: f64,
    difference_tolerance: f64,
) -> [f64; 4]
where
    R: TipKinematics<N, TIPS> + Dynamics<N>,
{
    let (reference, frames) = reference(file);
    let names: Vec<&str> = frames.iter().map(|f| f.name.as_str()).collect();
    let mut worst = [0.0f64; 4];
    for (k, s) in samples(&format!("trees/{file}")).iter().enumerate() {
        let (q, qd) = (vector::<N>(&s["q"]), vector::<N>(&s["qd"]));
        let poses = robot.tip_poses(&q);
        let (in_base, in_tip) = (
            robot.tip_jacobians_in_base(&q),
            robot.tip_jacobians_in_tip(&q),
        );
        let (bias_base, bias_tip) = (
            robot.tip_acceleration_biases_in_base(&q, &qd),
            robot.tip_acceleration_biases_in_tip(&q, &qd),
        );
        // A wrench per tip, different for each, in its tip's frame and in base axes.
        let wrenches: [[f64; 6]; TIPS] =
            core::array::from_fn(|t| core::array::from_fn(|c| (c as f64 - 2.5) * (t as f64 + 1.0)));
        let (mut want_tip, mut want_base) = (vec![0.0; N], vec![0.0; N]);
        for t in 0..TIPS {
            let name = tip_names[t];
            let tip = &s["tips"][name];
            let (pose, j) = (rows(&tip["pose"]), rows(&tip["jacobian"]));
            let r: Vec<Vec<f64>> = pose[..3].iter().map(|row| row[..3].to_vec()).collect();
            let local = in_axes(&j, &r);
            let got_pose = pose_rows(&poses[t]);
            let want_pose: Vec<f64> = pose[..3].iter().flatten().copied().collect();
            let flat = |m: &[[f64; N]; 6]| m.iter().flatten().copied().collect::<Vec<f64>>();
            let frame = &frames[names.iter().position(|n| *n == name).expect("a frame")];
            let by_differences = bias_by_differences(&reference, frame, &q, &qd);
            let bias_in_tip = turned(&by_differences, &r);
            for i in 0..N {
                for c in 0..6 {
                    want_tip[i] += local[c][i] * wrenches[t][c];
                    want_base[i] += j[c][i] * wrenches[t][c];
                }
            }
            let checks = [
                (0, "pose", got_pose, want_pose),
                (1, "Jacobian in base", flat(&in_base[t]), j.concat()),
                (1, "Jacobian in tip", flat(&in_tip[t]), local.concat()),
                (2, "J'q' in base", bias_base[t].to_vec(), by_differences),
                (2, "J'q' in tip", bias_tip[t].to_vec(), bias_in_tip),
            ];
            for (slot, what, got, want) in checks {
                let e = error(&got, &want, relative);
                let bound = if slot == 2 {
                    difference_tolerance
                } else {
                    tolerance
                };
                assert!(
                    e < bound,
                    "{file} sample {k} tip {name}: {what} off by {e:e}"
                );
                worst[slot] = worst[slot].max(e);
            }
        }
        let torques = [
            (
                robot.joint_torques_for_tip_wrenches(&q, &wrenches),
                want_tip,
            ),
            (
                robot.joint_torques_for_tip_wrenches_in_base(&q, &wrenches),
                want_base,
            ),
        ];
        for (got, want) in torques {
            let e = error(&got, &want, relative);
            assert!(
                e < tolerance,
                "{file} sample {k}: wrench torques off by {e:e}"
            );
            worst[3] = worst[3].max(e);
        }
    }
    eprintln!("trees/{file}: worst pose, J, J'q', torques {worst:?}");
    worst
}

#[test]
fn the_allegro_hands_fingertips_against_pinocchio() {
    assert_eq!(
        AllegroTips::TIP_NAMES,
        [
            "link_3.0_tip",
            "link_7.0_tip",
            "link_11.0_tip",
            "link_15.0_tip"
        ]
    );
    assert_eq!(
        (
            AllegroTips::TIP_LINK_7_0_TIP,
            AllegroTips::TIP_LINK_15_0_TIP
        ),
        (1, 3)
    );
    assert_eq!(<AllegroTips as TipKinematics<16, 4>>::TIP_COUNT, 4);
    // 1e-8 relative: the thumb's first axis, 9e-10 rad off parallel in the URDF, is taken as
    // parallel by the front end (see `urdf_trees::allegro_hand_matches_pinocchio`).
    check(
        &AllegroTips,
        AllegroTips::TIP_NAMES,
        "allegro_right_hand.json",
        true,
        1e-8,
        1e-8,
    );
}

#[test]
fn the_pandas_free_fingers_are_its_leaves_against_pinocchio() {
    assert_eq!(
        PandaFreeFingers::TIP_NAMES,
        ["panda_leftfinger", "panda_rightfinger"]
    );
    assert_eq!(PandaFreeFingers::TIP_PANDA_RIGHTFINGER, 1);
    check(
        &PandaFreeFingers,
        PandaFreeFingers::TIP_NAMES,
        "panda_fingers_no_mimic.json",
        false,
        1e-12,
        1e-8,
    );
}

/// PUMA 560 asking for the family: one tip, its last link, whose kinematics are the hand's
/// (the description declares no tool).
#[derive(Dynamics)]
#[dynamics(
    file = "data/reference/robots/puma560.json",
    check_inertia = false,
    tip_kinematics = true
)]
struct PumaTip;

#[test]
fn a_serial_robot_that_asks_has_one_tip_its_hand() {
    assert_eq!(PumaTip::TIP_NAMES, ["link6"]);
    assert_eq!(PumaTip::TIP_LINK6, 0);
    let q = [0.3, -0.7, 1.1, 0.4, -0.9, 2.0];
    let qd = [0.5, -0.2, 0.9, -1.1, 0.3, 0.7];
    // The same nodes of the graph, in another family's function: equal to rounding.
    let close = |a: Vec<f64>, b: Vec<f64>| {
        let e = a
            .iter()
            .zip(&b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        assert!(e < 1e-12, "{a:?} against {b:?}");
    };
    let flat = |m: [[f64; 6]; 6]| m.concat();
    let (pose, hand) = (PumaTip.tip_poses(&q)[0], PumaTip.hand_pose(&q));
    close(pose.homogeneous().concat(), hand.homogeneous().concat());
    close(
        flat(PumaTip.tip_jacobians_in_base(&q)[0]),
        flat(PumaTip.hand_jacobian_in_base(&q)),
    );
    close(
        flat(PumaTip.tip_jacobians_in_tip(&q)[0]),
        flat(PumaTip.hand_jacobian_in_hand(&q)),
    );
    close(
        PumaTip.tip_acceleration_biases_in_tip(&q, &qd)[0].to_vec(),
        PumaTip.hand_acceleration_bias_in_hand(&q, &qd).to_vec(),
    );
    let w = [[1.0, -2.0, 3.0, 0.5, -0.25, 0.125]];
    let (tip, hand) = (
        PumaTip.joint_torques_for_tip_wrenches(&q, &w),
        PumaTip.joint_torques_for_hand_wrench(&q, &w[0]),
    );
    assert!(
        (0..6).all(|i| (tip[i] - hand[i]).abs() < 1e-12),
        "{tip:?} against {hand:?}"
    );
}

/// The fingertips of the mimic Panda in its coordinates: the poses, and the Jacobians `J S`
/// (the second finger's column carried onto the first's), against Pinocchio 4.1's mimic model;
/// the wrench torques against `Sᵀ Jᵀ F` from the same Jacobians.
#[test]
fn the_mimic_pandas_fingertips_in_its_coordinates() {
    let mut worst = 0.0f64;
    for s in samples("trees/panda_fingers.json") {
        let q = vector::<8>(&s["q"]);
        let poses = PandaMimicTips.tip_poses(&q);
        let in_base = PandaMimicTips.tip_jacobians_in_base(&q);
        let wrenches: [[f64; 6]; 2] =
            core::array::from_fn(|t| core::array::from_fn(|c| c as f64 - 1.5 * t as f64));
        let mut want_torques = [0.0; 8];
        for (t, name) in PandaMimicTips::TIP_NAMES.iter().enumerate() {
            let tip = &s["tips"][*name];
            let (pose, j) = (rows(&tip["pose"]), rows(&tip["jacobian"]));
            let want_pose: Vec<f64> = pose[..3].iter().flatten().copied().collect();
            let got_j: Vec<f64> = in_base[t].iter().flatten().copied().collect();
            for (i, torque) in want_torques.iter_mut().enumerate() {
                *torque += (0..6).map(|c| j[c][i] * wrenches[t][c]).sum::<f64>();
            }
            worst = worst
                .max(error(&pose_rows(&poses[t]), &want_pose, false))
                .max(error(&got_j, &j.concat(), false));
        }
        let torques = PandaMimicTips.joint_torques_for_tip_wrenches_in_base(&q, &wrenches);
        worst = worst.max(error(&torques, &want_torques, false));
    }
    assert!(worst < 1e-12, "off by {worst:e}");
    assert!(
        worst > 0.0,
        "every quantity exact: the check compares nothing"
    );
}
