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

#[cfg(test)]
mod tests {
    use super::gravity_torques;
    use crate::algo::{rnea, test_chain, V3};

    /// Equal to Newton-Euler at rest, for the chain as given and regrouped, with gravity along
    /// no axis.
    #[test]
    fn equals_newton_euler_at_rest() {
        let gravity = V3::new(1.3, -4.1, -8.7);
        let zeros = [0.0; 5];
        for q in [[0.3, -1.1, 0.25, 2.0, -0.6], [2.9, 0.4, -0.3, -1.7, 1.2]] {
            for regroup in [false, true] {
                let chain = test_chain(&q);
                let chain = if regroup { chain.regrouped() } else { chain };
                let by_composites = gravity_torques(&chain, gravity);
                let by_newton_euler = rnea(&chain, &zeros, &zeros, gravity);
                for (a, b) in by_composites.iter().zip(&by_newton_euler) {
                    assert!(
                        (a - b).abs() < 1e-12,
                        "{by_composites:?} vs {by_newton_euler:?}"
                    );
                }
            }
        }
    }
}
