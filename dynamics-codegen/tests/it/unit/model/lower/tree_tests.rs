//! The lowering of trees against an independent product along the antecedents: on random
//! trees given URDF style, every user link frame `L_p P_i M_i(q_i)` equals the D-H frame composed
//! from the Khalil-Kleinfinger rows (`Rotz(γ) Transz(b)` before each modified row) times the
//! link's pose; a tree lowered by hand; nearly parallel axes.

use crate::unit::model::lower::tests::{
    close, dh_frames, identity, modified_dh, mul, num, placement, pose_matrix, random_joint,
    random_robot, rodrigues, rotation, user_frames, M4,
};
use dynamics_codegen::model::lower_frames;
use dynamics_codegen::model::{
    AxisFrame, Branch, Convention, Joint, JointKind, Placement, Robot, Value,
};
use dynamics_test_support::Rng;

/// A random tree: each joint hangs from the base or an earlier joint, more often the one before.
fn random_tree(rng: &mut Rng) -> Robot {
    let mut robot = random_robot(rng);
    for j in 0..robot.dof() {
        let parent = match rng.below(4) {
            0 => None,
            1 => Some(rng.below(j.max(1))).filter(|_| j > 0),
            _ => j.checked_sub(1),
        }
        .filter(|p| *p < j);
        robot.joints[j].branch = Some(Branch {
            parent,
            gamma: Value::zero(),
            b: Value::zero(),
        });
    }
    robot
}

/// Frames composed along each joint's antecedents: `frame(parent) · step(joint, q)`.
fn compose(robot: &Robot, root: &M4, step: impl Fn(&Joint, f64) -> M4, q: &[f64]) -> Vec<M4> {
    let mut frames: Vec<M4> = Vec::new();
    for (i, (joint, &qi)) in robot.joints.iter().zip(q).enumerate() {
        let parent = robot.parent(i).map_or(root, |p| &frames[p]);
        let frame = mul(parent, &step(joint, qi));
        frames.push(frame);
    }
    frames
}

/// The user's link frame i in its antecedent's: `P_i M_i(q_i)`.
fn user_step(joint: &Joint, q: f64) -> M4 {
    let frame = joint.frame.as_ref().unwrap();
    let axis = frame.axis.clone().map(|v| num(&v));
    let o = &frame.origin;
    let motion = match joint.kind {
        JointKind::Revolute => rotation(rodrigues(axis, q), [0.0; 3]),
        JointKind::Prismatic => rotation(rodrigues(axis, 0.0), axis.map(|x| x * q)),
    };
    let xyz = o.xyz.clone().map(|v| num(&v));
    mul(&placement(xyz, o.rpy.clone().map(|v| num(&v))), &motion)
}

/// D-H frame i in its antecedent's: `Rotz(γ) Transz(b) Rotx(α) Transx(a) Rotz(θ) Transz(d)`.
fn khalil_step(j: &Joint, q: f64) -> M4 {
    let (theta, d) = match j.kind {
        JointKind::Revolute => (num(&j.theta) + q, num(&j.d)),
        JointKind::Prismatic => (num(&j.theta), num(&j.d) + q),
    };
    let (gamma, b) = j
        .branch
        .as_ref()
        .map_or((0.0, 0.0), |br| (num(&br.gamma), num(&br.b)));
    let turn = rotation(rodrigues([0.0, 0.0, 1.0], gamma), [0.0, 0.0, b]);
    mul(&turn, &modified_dh(num(&j.alpha), num(&j.a), theta, d))
}

#[test]
fn random_trees_lower_to_khalil_kleinfinger_rows_with_the_same_kinematics() {
    let mut rng = Rng::new(41);
    let mut branching = 0;
    for case in 0..400 {
        let user = random_tree(&mut rng);
        branching += usize::from(user.is_tree());
        let mut lowered = user.clone();
        lower_frames(&mut lowered).unwrap_or_else(|p| panic!("case {case}: {p:?}"));
        assert_eq!(lowered.convention, Convention::Modified);
        for _ in 0..3 {
            let q = rng.vector(user.dof(), -3.0, 3.0);
            let want = compose(&user, &identity(), user_step, &q);
            let dh = compose(&lowered, &pose_matrix(&lowered.base), khalil_step, &q);
            for (i, (w, d)) in want.iter().zip(&dh).enumerate() {
                let got = mul(d, &pose_matrix(&lowered.joints[i].link_pose));
                close(&got, w, &format!("case {case}, link {}", i + 1));
            }
        }
        // A first child's antecedent x is its own normal: γ = b = 0.
        for (i, joint) in lowered.joints.iter().enumerate() {
            let first = (0..i).all(|k| lowered.parent(k) != lowered.parent(i));
            let branch = joint.branch.as_ref().unwrap();
            if first && lowered.parent(i).is_some() {
                assert!(
                    branch.gamma.is_zero() && branch.b.is_zero(),
                    "case {case}, {i}"
                );
            }
        }
    }
    assert!(branching > 200, "{branching} trees of 400");
}

/// Joint 1 about z at the base origin; joints 2 and 3 hang from it, 2 at x = 1 about z, 3 at
/// z = 1/2 about y; joint 4 hangs from it at y = 1, about z. Frame 1's x follows the normal to
/// joint 2 (+x); joint 3's normal from axis 1 meets it at height 1/2 along +x (the sign that
/// keeps γ = 0): b = 1/2, α = −90°; joint 4's, parallel to axis 1, points along +y: γ = 90°,
/// a = 1.
#[test]
fn a_hand_lowered_tree() {
    let mut rng = Rng::new(3);
    let joint = |rng: &mut Rng, parent: Option<usize>, xyz: [f64; 3], axis: [f64; 3]| Joint {
        kind: JointKind::Revolute,
        frame: Some(AxisFrame {
            origin: Placement {
                xyz: xyz.map(Value::from_f64),
                rpy: [0.0; 3].map(Value::from_f64),
            },
            axis: axis.map(Value::from_f64),
        }),
        branch: Some(Branch {
            parent,
            gamma: Value::zero(),
            b: Value::zero(),
        }),
        ..random_joint(rng)
    };
    let z = [0.0, 0.0, 1.0];
    let mut robot = Robot {
        joints: vec![
            joint(&mut rng, None, [0.0; 3], z),
            joint(&mut rng, Some(0), [1.0, 0.0, 0.0], z),
            joint(&mut rng, Some(0), [0.0, 0.0, 0.5], [0.0, 1.0, 0.0]),
            joint(&mut rng, None, [0.0, 1.0, 0.0], z),
        ],
        ..random_robot(&mut rng)
    };
    lower_frames(&mut robot).unwrap();
    let row = |i: usize| {
        let j = &robot.joints[i];
        let br = j.branch.as_ref().unwrap();
        [&br.gamma, &br.b, &j.alpha, &j.a, &j.theta, &j.d].map(ToString::to_string)
    };
    assert_eq!(row(0), ["0", "0", "0", "0", "0", "0"]);
    assert_eq!(row(1), ["0", "0", "0", "1", "0", "0"]);
    assert_eq!(row(2), ["0", "1/2", "-1/2 * pi", "0", "0", "0"]);
    assert_eq!(row(3), ["1/2 * pi", "0", "0", "1", "0", "0"]);
}

/// Axes a billionth of a radian off parallel (the Allegro hand's thumb against its first
/// finger, as the URDF's rounded angles make them) are taken as parallel: the skew formula's
/// `1 − b²` rounds to 0 there. The frames still agree to the tilt times the offset.
#[test]
fn nearly_parallel_axes_lower_as_parallel_ones() {
    let mut rng = Rng::new(9);
    for tilt in [1e-9, -3e-8, 5e-7] {
        let mut robot = random_robot(&mut rng);
        robot.joints.truncate(2);
        while robot.joints.len() < 2 {
            robot.joints.push(random_joint(&mut rng));
        }
        // Axes 0.3 rad from z and `tilt` apart: a tilted placement would snap to none.
        let places = [([0.0, 0.0, 0.0], 0.3), ([0.1, 0.0, 0.05], 0.3 + tilt)];
        for (joint, (xyz, angle)) in robot.joints.iter_mut().zip(places) {
            let (s, c) = f64::sin_cos(angle);
            joint.frame = Some(AxisFrame {
                origin: Placement {
                    xyz: xyz.map(Value::from_f64),
                    rpy: [0.0; 3].map(Value::from_f64),
                },
                axis: [0.0, -s, c].map(Value::from_f64),
            });
        }
        let mut lowered = robot.clone();
        lower_frames(&mut lowered).unwrap_or_else(|p| panic!("tilt {tilt}: {p:?}"));
        let q = rng.vector(2, -3.0, 3.0);
        let (want, dh) = (user_frames(&robot, &q), dh_frames(&lowered, &q));
        for (i, (w, d)) in want.iter().zip(&dh).enumerate() {
            let got = mul(d, &pose_matrix(&lowered.joints[i].link_pose));
            for r in 0..4 {
                for c in 0..4 {
                    assert!((got[r][c] - w[r][c]).abs() < 1e-6, "tilt {tilt}, link {i}");
                }
            }
        }
    }
}
