use super::test_chain;
use dynamics_codegen::algo::body::rotate_inertia;
use dynamics_codegen::algo::Mat3;
use std::ops::Add;

/// A body carried to the parent is the same moved before the twist or after it, and its
/// first moment is `R h + m p` (the inertia is checked end to end, by the derivative test
/// of `crba` and the reference data).
#[test]
fn carrying_a_body() {
    let chain = test_chain(&[0.3, -1.1, 0.25, 2.0, -0.6]);
    for joint in &chain.joints[1..] {
        let b = &joint.body;
        let mut before = *joint;
        before.move_before_twist = true;
        let (x, y) = (joint.body_to_parent(b), before.body_to_parent(b));
        let r = joint.rotation();
        let h = r.mul_vec(b.h).add(joint.offset().scale(b.mass));
        for (u, v) in [
            (x.h.x, y.h.x),
            (x.h.y, y.h.y),
            (x.h.z, y.h.z),
            (x.h.x, h.x),
            (x.h.y, h.y),
            (x.h.z, h.z),
        ] {
            assert!((u - v).abs() < 1e-14, "{u} vs {v}");
        }
        for (u, v) in x.inertia.iter().zip(y.inertia) {
            assert!((u - v).abs() < 1e-14, "{:?} vs {:?}", x.inertia, y.inertia);
        }
    }
}

/// The plane-rotation formulas agree with `R I Rᵀ` of the full matrices, for Rotz then
/// Rotx (the order of `ChainJoint::rotation`).
#[test]
fn rotating_an_inertia_tensor() {
    let i = [0.7, 0.5, 0.4, -0.05, 0.08, 0.03];
    for (theta, alpha) in [
        (0.3f64, -1.2f64),
        (2.5, 0.0),
        (-1.1, std::f64::consts::FRAC_PI_2),
    ] {
        let (st, ct) = theta.sin_cos();
        let (sa, ca) = alpha.sin_cos();
        let by_planes = rotate_inertia(rotate_inertia(i, st, ct, 0, 1), sa, ca, 1, 2);
        let r = Mat3::rot_x(sa, ca).mul(&Mat3::rot_z(st, ct));
        let full = Mat3::symmetric(i).congruence(&r);
        for (a, b) in by_planes.iter().zip(full) {
            assert!((a - b).abs() < 1e-15, "{by_planes:?} vs {full:?}");
        }
    }
}
