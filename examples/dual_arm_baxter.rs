//! A dual-arm robot holding a box with both hands: Baxter from its URDF, its two arms the
//! branches to the grippers' end-point frames `left_gripper` and `right_gripper` (14 joints,
//! the head and the grippers' fingers cut off, the gripper bases part of the wrists), each a
//! tip of `TipKinematics`. The box (2 kg) hangs between the hands, each
//! carrying half its weight and squeezing it with 30 N along the line between them; the joint
//! torques that hold it are `Σ_t J_tᵀ F_t` of the two hands' wrenches plus the gravity torques.
//!
//! ```text
//! cargo run --release -p dynamics-examples --example dual_arm_baxter
//! ```
//!
//! It checks itself and fails otherwise: the hands' forces hold the box's weight and their
//! moments about its centre cancel; the torques equal the virtual power of the wrenches along
//! random joint velocities (`τ · q̇ = Σ F_t · J_t q̇`); the tips' frames give the same torques
//! as base axes; and each hand's wrench loads its own arm alone.

use dynamics_runtime::{Dynamics, TipKinematics};

/// Baxter's arms, to the hands.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/trees/baxter.urdf",
    base = "base",
    tips = ["left_gripper", "right_gripper"]
)]
struct Baxter;

const N: usize = 14;
const BOX_KG: f64 = 2.0;
const SQUEEZE_N: f64 = 30.0;
const G: f64 = 9.81;

fn main() {
    let robot = Baxter;
    let q = posture();
    let poses = robot.tip_poses(&q);
    let (left, right) = (Baxter::TIP_LEFT_GRIPPER, Baxter::TIP_RIGHT_GRIPPER);
    let (pl, pr) = (poses[left].position, poses[right].position);
    let centre: [f64; 3] = core::array::from_fn(|i| 0.5 * (pl[i] + pr[i]));
    let width = distance(&pl, &pr);
    // From the left hand to the right: the left hand pushes along it, the right against it.
    let u: [f64; 3] = core::array::from_fn(|i| (pr[i] - pl[i]) / width);
    let up = 0.5 * BOX_KG * G;
    let force = |sign: f64| -> [f64; 6] {
        let f = core::array::from_fn::<f64, 3, _>(|i| sign * SQUEEZE_N * u[i]);
        [f[0], f[1], f[2] + up, 0.0, 0.0, 0.0]
    };
    // What each hand exerts on the box, in base axes, about its own origin.
    let mut wrenches = [[0.0; 6]; 2];
    wrenches[left] = force(1.0);
    wrenches[right] = force(-1.0);
    let holding = robot.joint_torques_for_tip_wrenches_in_base(&q, &wrenches);
    let gravity = robot.gravity_torques(&q);
    let total: [f64; N] = core::array::from_fn(|i| gravity[i] + holding[i]);

    println!("Baxter holding a {BOX_KG} kg box, squeezed with {SQUEEZE_N} N");
    for (name, t) in Baxter::TIP_NAMES.iter().zip(0..) {
        let [x, y, z] = poses[t].position;
        let w = wrenches[t];
        println!(
            "  {name:>13} at ({x:6.3}, {y:6.3}, {z:6.3}) m, force ({:6.2}, {:6.2}, {:6.2}) N",
            w[0], w[1], w[2]
        );
    }
    println!(
        "  box centre ({:.3}, {:.3}, {:.3}) m, width {width:.3} m",
        centre[0], centre[1], centre[2]
    );
    let jacobians = robot.tip_jacobians_in_base(&q);
    println!("\n joint  arm    gravity    box (Jᵀ F)      total   [N·m]");
    for i in 0..N {
        let arm = if jacobians[left].iter().any(|row| row[i] != 0.0) {
            "left"
        } else {
            "right"
        };
        println!(
            " {:>5}  {arm:<5} {:>9.3} {:>13.3} {:>10.3}",
            i + 1,
            gravity[i],
            holding[i],
            total[i]
        );
    }

    check_balance(&wrenches, &[pl, pr], &centre);
    check_virtual_power(&robot, &q, &wrenches, &holding);
    check_tip_frames(&robot, &q, &wrenches, &holding);
    check_arms_apart(&robot, &q, &wrenches, left, right);
    println!("\nchecks passed: the box's weight held, its moments balanced, τ·q̇ = Σ F·J q̇, the");
    println!("tips' frames and base axes agree, each hand loads its own arm alone");
}

/// Both arms bent forward, the right mirroring the left (joint 0 to 6 the right arm, as the
/// file mounts it first; 7 to 13 the left).
fn posture() -> [f64; N] {
    let left = [0.3, -0.4, -1.4, 1.6, 0.5, 1.2, 0.0];
    let mirror = [-1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0];
    core::array::from_fn(|i| {
        if i < 7 {
            mirror[i] * left[i]
        } else {
            left[i - 7]
        }
    })
}

fn distance(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The hands' forces add up to the box's weight upward, and their moments about its centre
/// (plus their own moments, zero here) cancel.
fn check_balance(wrenches: &[[f64; 6]; 2], at: &[[f64; 3]; 2], centre: &[f64; 3]) {
    let mut force = [0.0; 3];
    let mut moment = [0.0; 3];
    for (w, p) in wrenches.iter().zip(at) {
        let f = [w[0], w[1], w[2]];
        let arm: [f64; 3] = core::array::from_fn(|i| p[i] - centre[i]);
        let m = cross(&arm, &f);
        for i in 0..3 {
            force[i] += f[i];
            moment[i] += m[i] + w[3 + i];
        }
    }
    let weight = [0.0, 0.0, BOX_KG * G];
    assert!(
        (0..3).all(|i| (force[i] - weight[i]).abs() < 1e-12),
        "forces {force:?}"
    );
    assert!(moment.iter().all(|m| m.abs() < 1e-12), "moments {moment:?}");
}

/// `τ · q̇ = Σ_t F_t · (J_t q̇)` along a few joint velocities: the torques are the wrenches'
/// virtual power (the principle that gives `τ = Jᵀ F`).
fn check_virtual_power(robot: &Baxter, q: &[f64; N], wrenches: &[[f64; 6]; 2], tau: &[f64; N]) {
    let jacobians = robot.tip_jacobians_in_base(q);
    for k in 0..5 {
        let qd: [f64; N] = core::array::from_fn(|i| ((i * 7 + k * 3) % 11) as f64 / 5.0 - 1.0);
        let power: f64 = (0..N).map(|i| tau[i] * qd[i]).sum();
        let mut by_wrenches = 0.0;
        for (j, w) in jacobians.iter().zip(wrenches) {
            for (row, w) in j.iter().zip(w) {
                by_wrenches += w * (0..N).map(|i| row[i] * qd[i]).sum::<f64>();
            }
        }
        let scale = power.abs().max(1.0);
        assert!(
            (power - by_wrenches).abs() < 1e-12 * scale,
            "{power} against {by_wrenches}"
        );
    }
}

/// The same wrenches given in each hand's frame (`[Rᵀ f; Rᵀ m]`) give the same torques.
fn check_tip_frames(robot: &Baxter, q: &[f64; N], wrenches: &[[f64; 6]; 2], tau: &[f64; N]) {
    let poses = robot.tip_poses(q);
    let in_tips: [[f64; 6]; 2] = core::array::from_fn(|t| {
        let r = poses[t].rotation;
        let w = wrenches[t];
        core::array::from_fn(|i| {
            let part = i / 3 * 3;
            (0..3).map(|k| r[k][i % 3] * w[part + k]).sum()
        })
    });
    let again = robot.joint_torques_for_tip_wrenches(q, &in_tips);
    assert!((0..N).all(|i| (again[i] - tau[i]).abs() < 1e-12 * tau[i].abs().max(1.0)));
}

/// A wrench at one hand moves no joint of the other arm.
fn check_arms_apart(
    robot: &Baxter,
    q: &[f64; N],
    wrenches: &[[f64; 6]; 2],
    left: usize,
    right: usize,
) {
    let jacobians = robot.tip_jacobians_in_base(q);
    let mut only_left = *wrenches;
    only_left[right] = [0.0; 6];
    let tau = robot.joint_torques_for_tip_wrenches_in_base(q, &only_left);
    for i in 0..N {
        let left_arm = jacobians[left].iter().any(|row| row[i] != 0.0);
        assert!(
            left_arm || tau[i] == 0.0,
            "joint {} of the right arm loaded",
            i + 1
        );
    }
}
