use super::parallel_chain;
use dynamics_codegen::algo::rnea::{rnea, Rates};
use dynamics_codegen::algo::{Mat3, V3};
use std::ops::Add;

/// Rates turned through the sums of parallel joints' angles, and moments turned back the
/// same way, give the torques of the joint-by-joint recursion.
#[test]
fn summing_angles_of_parallel_joints() {
    let q = [0.3, -1.1, 0.7, 2.0, -0.6, 1.4, 0.15];
    let qd = [0.8, -0.4, 1.3, -2.1, 0.5, 0.9, -0.3];
    let qdd = [-1.2, 0.6, 0.2, 1.7, -0.9, 0.4, 0.8];
    let gravity = V3::new(0.5, -1.0, -9.7);
    for symmetric_tip in [false, true] {
        let chain = parallel_chain(&q, symmetric_tip);
        let summed = chain.clone().summing_angles(true);
        let flags: Vec<bool> = summed.joints.iter().map(|j| j.sum_angles).collect();
        let expected = [false, false, true, true, false, true, false];
        assert_eq!(flags, expected[..chain.joints.len()]);
        let n = chain.joints.len();
        let plain = rnea(&chain, &qd[..n], &qdd[..n], gravity);
        let by_sums = rnea(&summed, &qd[..n], &qdd[..n], gravity);
        for (a, b) in plain.iter().zip(&by_sums) {
            assert!((a - b).abs() < 1e-12, "{plain:?} vs {by_sums:?}");
        }
    }
}

/// The moment read off `U` equals `I ω̇ + ω × I ω` computed directly.
#[test]
fn inertial_moment_from_u() {
    let inertia = [0.7, 0.5, 0.4, -0.05, 0.08, 0.03];
    for (w, wd) in [
        (V3::new(0.3, -1.2, 2.1), V3::new(-0.7, 0.4, 1.9)),
        (V3::new(-2.0, 0.1, 0.0), V3::new(0.0, 3.3, -0.2)),
    ] {
        let i = Mat3::symmetric(inertia);
        let direct = i.mul_vec(wd).add(w.cross(i.mul_vec(w)));
        let by_u = Rates::new(w, wd).inertial_moment(inertia);
        for (a, b) in [(by_u.x, direct.x), (by_u.y, direct.y), (by_u.z, direct.z)] {
            assert!((a - b).abs() < 1e-14, "{a} vs {b}");
        }
    }
}
