//! Kinetic and potential energy of the links (eqs. 6.39, 6.40 of the book without actuators
//! and springs, which the caller adds).
//!
//! `K = Σ ½ (m v·v + 2 v·(ω × h) + ω·I ω)` with `v`, `ω` the velocity of J_i's origin and the
//! angular velocity of link i; `P = −Σ (m_i g·p_i + g_i·h_i)` with `p_i` the origin of J_i in the
//! base and `g_i` the gravity vector in J_i axes; each link's velocities and `g_i`, `g·p_i`
//! follow from its antecedent's.

use super::{Chain, JointKind, Scalar, V3};
use crate::symbolic::Number;
use std::ops::Add;

/// Kinetic energy of the links of `chain` moving with velocities `qd`.
/// `zero` gives the scalar context.
pub fn kinetic_energy<S: Scalar>(chain: &Chain<S>, qd: &[S], zero: S) -> S {
    let mut twists: Vec<(V3<S>, V3<S>)> = Vec::with_capacity(chain.joints.len());
    let mut twice = zero;
    for (i, j) in chain.joints.iter().enumerate() {
        let (w, v) = j
            .parent
            .map_or((V3::zero(zero), V3::zero(zero)), |p| twists[p]);
        let v_parent = v.add(w.cross(j.offset()));
        let mut v = j.to_child(v_parent);
        let mut w = j.to_child(w);
        match j.kind {
            JointKind::Revolute => w.z = w.z + qd[i],
            JointKind::Prismatic => v.z = v.z + qd[i],
        }
        let b = &j.body;
        twice = twice
            + b.mass * v.dot(v)
            + (v.dot(w.cross(b.h)) + v.dot(w.cross(b.h)))
            + w.dot(b.inertia_mul(w));
        twists.push((w, v));
    }
    zero.constant(Number::ratio(1, 2).unwrap_or(Number::ONE)) * twice
}

/// Potential energy of the links of `chain` under `gravity`, zero with every centre of mass at
/// the base origin.
pub fn potential_energy<S: Scalar>(chain: &Chain<S>, gravity: V3<S>) -> S {
    let zero = gravity.x.zero();
    // Per joint, gravity in its axes and `g · p_i`.
    let mut at: Vec<(V3<S>, S)> = Vec::with_capacity(chain.joints.len());
    let mut total = zero;
    for j in &chain.joints {
        let (g, height) = j.parent.map_or((gravity, zero), |p| at[p]);
        let height = height + g.dot(j.offset());
        let g = j.to_child(g);
        total = total + j.body.mass * height + g.dot(j.body.h);
        at.push((g, height));
    }
    -total
}
