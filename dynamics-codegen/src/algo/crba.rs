//! Composite rigid body algorithm: the mass matrix `M(q)`, the book's D_ij (eq. 6.43)
//! without actuator inertia.
//!
//! The composite body of links i..n, `Ic_i = body_i + X_{i+1}(Ic_{i+1})`, moved by a unit
//! acceleration of joint i alone exerts the wrench `(f, n) = (z × h, I z)` (revolute) or
//! `(m z, h × z)` (prismatic) at J_i. `M_ii` is its component on joint i's axis; carried to
//! J_j (`f ← R f`, `n ← R n + p × R f`) its component on joint j's axis is `M_ji`. Column j of
//! the result equals [`super::rnea`] with `qd = 0`, `qdd = e_j` and no gravity.

use super::{Body, Chain, JointKind, Scalar, V3};
use std::ops::Add;

/// The joint-space mass matrix of `chain`, full and symmetric.
pub fn crba<S: Scalar>(chain: &Chain<S>) -> Vec<Vec<S>> {
    let n = chain.joints.len();
    let Some(first) = chain.joints.first() else {
        return Vec::new();
    };
    let zero = first.a.zero();
    let mut m = vec![vec![zero; n]; n];
    let mut composite: Vec<Body<S>> = chain.joints.iter().map(|j| j.body).collect();
    for i in (0..n.saturating_sub(1)).rev() {
        let moved = chain.joints[i + 1].body_to_parent(&composite[i + 1]);
        composite[i] = composite[i].add(&moved);
    }
    for i in 0..n {
        let c = &composite[i];
        let one = zero.one();
        let z = V3::new(zero, zero, one);
        let (mut f, mut nn) = match chain.joints[i].kind {
            JointKind::Revolute => (z.cross(c.h), c.inertia_mul(z)),
            JointKind::Prismatic => (z.scale(c.mass), c.h.cross(z)),
        };
        let axis = |k: usize, f: V3<S>, nn: V3<S>| match chain.joints[k].kind {
            JointKind::Revolute => nn.z,
            JointKind::Prismatic => f.z,
        };
        m[i][i] = axis(i, f, nn);
        for j in (0..i).rev() {
            let child = &chain.joints[j + 1];
            let rf = child.to_parent(f);
            nn = child.to_parent(nn).add(child.offset().cross(rf));
            f = rf;
            m[j][i] = axis(j, f, nn);
            m[i][j] = m[j][i];
        }
    }
    m
}
