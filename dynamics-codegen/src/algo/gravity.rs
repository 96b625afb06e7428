//! Gravity torques from composite first moments: `g(q) = ∂P/∂q`, with
//! `g_i = −gravity · (z_i × H_i)` for a revolute joint and `g_i = −M_i gravity · z_i` for a
//! prismatic one, where `M_i` and `H_i` are the mass and the first moment about J_i of links
//! i and its descendants (the composite bodies of [`super::crba`]; links i..n in a chain) and
//! `gravity` is expressed in J_i axes, carried out from the antecedent's.
//!
//! The gravity vector is carried outward and the composites inward independently, so the two
//! chains of rotations run side by side instead of one after the other as in Newton-Euler.

use super::{crba::composites, Chain, JointKind, Scalar, V3};

/// Joint torques (or forces) that hold `chain` still under `gravity` (the gravity acceleration
/// in the base frame). Springs are not included.
pub fn gravity_torques<S: Scalar>(chain: &Chain<S>, gravity: V3<S>) -> Vec<S> {
    let composite = composites(chain);
    let mut in_joint: Vec<V3<S>> = Vec::with_capacity(chain.joints.len());
    chain
        .joints
        .iter()
        .zip(&composite)
        .map(|(j, c)| {
            let g = j.to_child(j.parent.map_or(gravity, |p| in_joint[p]));
            in_joint.push(g);
            match j.kind {
                JointKind::Revolute => g.x * c.h.y - g.y * c.h.x,
                JointKind::Prismatic => -(g.z * c.mass),
            }
        })
        .collect()
}
