use super::{parallel_chain, test_chain};
use dynamics_codegen::algo::{projected_torques, LinkFrame, LinkFrames, Twist};
use dynamics_codegen::algo::{rnea, Chain, Mat3, V3};

const QD: [f64; 7] = [0.8, -0.4, 1.3, -2.1, 0.5, 0.9, -0.3];
const QDD: [f64; 7] = [-1.2, 0.6, 0.2, 1.7, -0.9, 0.4, 0.8];

fn assert_close(a: &[f64], b: &[f64]) {
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-12, "{a:?} vs {b:?}");
    }
}

/// The projection gives Newton-Euler's torques, revolute and prismatic joints, parallel
/// axes and oblique gravity.
#[test]
fn projection_is_newton_euler() {
    let q = [0.3, -1.1, 0.25, 2.0, -0.6, 1.4, 0.15];
    let gravity = V3::new(0.5, -1.0, -9.7);
    let chains: [Chain<f64>; 3] = [
        test_chain(&q),
        parallel_chain(&q, false),
        parallel_chain(&q, true),
    ];
    for chain in chains {
        let n = chain.joints.len();
        let expected = rnea(&chain, &QD[..n], &QDD[..n], gravity);
        let projected = projected_torques(&chain, None, &QD[..n], &QDD[..n], gravity);
        assert_close(&projected, &expected);
        let regrouped = chain.regrouped();
        let projected = projected_torques(&regrouped, None, &QD[..n], &QDD[..n], gravity);
        assert_close(&projected, &expected);
    }
}

/// Bodies given in frames of their own, in the joint frames or after the D-H frames: the
/// same torques as carried into the joint frames.
#[test]
fn bodies_in_frames_of_their_own() {
    let q = [-0.7, 0.4, 0.3, -1.3, 0.9];
    let gravity = V3::new(0.0, 0.3, -9.81);
    let in_joint_frames = test_chain(&q);
    let n = q.len();
    let poses: Vec<LinkFrame<f64>> = (0..n)
        .map(|l| {
            let x = l as f64;
            let (a, b) = (0.4 + 0.3 * x, -1.1 + 0.5 * x);
            LinkFrame {
                rotation: Mat3::rot_z(a.sin(), a.cos()).mul(&Mat3::rot_x(b.sin(), b.cos())),
                origin: V3::new(0.1 * x, -0.05, 0.2 - 0.03 * x),
            }
        })
        .collect();
    // The tip's twist, as the chain's next joint has it for the others.
    let tip = Twist {
        a: 0.13,
        sin_alpha: 0.6_f64.sin(),
        cos_alpha: 0.6_f64.cos(),
    };
    for tip_twist in [None, Some(tip)] {
        let mut in_own_frames = in_joint_frames.clone();
        let mut carried = in_joint_frames.clone();
        for (l, pose) in poses.iter().enumerate() {
            // Some body given in frame l: the joint frame's is the same body carried.
            let body = in_joint_frames.joints[(l + 2) % n].body;
            in_own_frames.joints[l].body = body;
            let mut body = pose.carry(&body);
            if tip_twist.is_some() {
                let next = in_joint_frames.joints.get(l + 1);
                let (a, s, c) = next.map_or((tip.a, tip.sin_alpha, tip.cos_alpha), |j| {
                    (j.a, j.sin_alpha, j.cos_alpha)
                });
                let twist = LinkFrame {
                    rotation: Mat3::rot_x(s, c),
                    origin: V3::new(a, 0.0, 0.0),
                };
                body = twist.carry(&body);
            }
            carried.joints[l].body = body;
        }
        let expected = rnea(&carried, &QD[..n], &QDD[..n], gravity);
        let frames = LinkFrames {
            tip_twist,
            poses: &poses,
        };
        let projected =
            projected_torques(&in_own_frames, Some(&frames), &QD[..n], &QDD[..n], gravity);
        assert_close(&projected, &expected);
    }
}
