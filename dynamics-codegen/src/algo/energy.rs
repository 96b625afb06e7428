//! Kinetic and potential energy of the links (eqs. 6.39, 6.40 of the book without actuators
//! and springs, which the caller adds).
//!
//! `K = Σ ½ (m v·v + 2 v·(ω × h) + ω·I ω)` with `v`, `ω` the velocity of J_i's origin and the
//! angular velocity of link i; `P = −Σ (m_i g·p_i + g_i·h_i)` with `p_i` the origin of J_i in the
//! base and `g_i` the gravity vector in J_i axes.

use super::{Chain, JointKind, Scalar, V3};
use crate::symbolic::Number;
use std::ops::Add;

/// Kinetic energy of the links of `chain` moving with velocities `qd`.
/// `zero` gives the scalar context.
pub fn kinetic_energy<S: Scalar>(chain: &Chain<S>, qd: &[S], zero: S) -> S {
    let mut w = V3::zero(zero);
    let mut v = V3::zero(zero);
    let mut twice = zero;
    for (i, j) in chain.joints.iter().enumerate() {
        let v_parent = v.add(w.cross(j.offset()));
        v = j.to_child(v_parent);
        w = j.to_child(w);
        match j.kind {
            JointKind::Revolute => w.z = w.z + qd[i],
            JointKind::Prismatic => v.z = v.z + qd[i],
        }
        let b = &j.body;
        twice = twice
            + b.mass * v.dot(v)
            + (v.dot(w.cross(b.h)) + v.dot(w.cross(b.h)))
            + w.dot(b.inertia_mul(w));
    }
    zero.constant(Number::ratio(1, 2).unwrap_or(Number::ONE)) * twice
}

/// Potential energy of the links of `chain` under `gravity`, zero with every centre of mass at
/// the base origin.
pub fn potential_energy<S: Scalar>(chain: &Chain<S>, gravity: V3<S>) -> S {
    let zero = gravity.x.zero();
    let mut g = gravity;
    let mut height = zero; // g · p_i
    let mut total = zero;
    for j in &chain.joints {
        height = height + g.dot(j.offset());
        g = j.to_child(g);
        total = total + j.body.mass * height + g.dot(j.body.h);
    }
    -total
}
