//! Runs of revolute joints about parallel axes (α = 0 between them): the angles of a run add,
//! `sin(Σ + θ) = sin Σ cos θ + cos Σ sin θ`, `cos(Σ + θ) = cos Σ cos θ − sin Σ sin θ`, so rates
//! and moments can be turned through a run in one step rather than joint by joint.

use super::{Chain, ChainJoint, JointKind, Scalar, V3};
use std::ops::Add;

impl<S: Scalar> ChainJoint<S> {
    /// Whether joint i turns about an axis parallel to joint i−1's, both revolute: α = 0
    /// exactly, so that J_{i−2} to J_i is `Rotx(α_{i−2}) Rotz(θ_{i−1} + θ_i)` up to a shift.
    pub fn parallel_to(&self, previous: &ChainJoint<S>) -> bool {
        self.kind == JointKind::Revolute
            && previous.kind == JointKind::Revolute
            && self.pre.is_none()
            && self.sin_alpha.is_zero()
            && (self.cos_alpha - self.cos_alpha.one()).is_zero()
    }
}

/// Carries wrenches towards the base, joint by joint, as [`ChainJoint::wrench_to_parent`]
/// does, except through a joint with [`ChainJoint::sum_angles`]: there only the moment's z
/// component (which the turn about z leaves alone) goes on at once; the rest waits, in the
/// axes of its link p, until the first joint of the run turns it by the run's angle up to p
/// ([`Chain::run_angles`]) in one step. A recursion that needs only the z components within a
/// run (the joint torques) skips the turns in between.
pub struct WrenchCarrier<'c, S> {
    chain: &'c Chain<S>,
    angles: Vec<Option<(S, S)>>,
    /// Moments across z waiting for the first joint of their run, with their link.
    pending: Vec<(V3<S>, usize)>,
}

impl<'c, S: Scalar> WrenchCarrier<'c, S> {
    /// A carrier for `chain`, holding no moments back.
    pub fn new(chain: &'c Chain<S>) -> WrenchCarrier<'c, S> {
        WrenchCarrier {
            chain,
            angles: chain.run_angles(),
            pending: Vec::new(),
        }
    }

    /// The wrench `(f, n)` at J_i in J_i axes, carried to J_{i−1}: the moment without the
    /// parts held back.
    pub fn to_parent(&mut self, i: usize, f: V3<S>, n: V3<S>) -> (V3<S>, V3<S>) {
        let joint = &self.chain.joints[i];
        let zero = f.x.zero();
        if joint.sum_angles {
            self.pending.push((V3::new(n.x, n.y, zero), i));
            return joint.wrench_from_turned(joint.to_turned(f), V3::new(zero, zero, n.z));
        }
        let mut turned = joint.to_turned(n);
        for (v, p) in self.pending.drain(..) {
            if let Some((s, c)) = self.angles[p] {
                turned = turned.add(V3::new(c * v.x - s * v.y, s * v.x + c * v.y, zero));
            }
        }
        joint.wrench_from_turned(joint.to_turned(f), turned)
    }
}

impl<S: Scalar> Chain<S> {
    /// The same chain with [`ChainJoint::sum_angles`] set to `on` for every joint parallel to
    /// the one before it. Not in a tree: the recursions' runs follow the joints' order, which
    /// there is not the path from a joint to its antecedent.
    #[must_use]
    pub fn summing_angles(mut self, on: bool) -> Chain<S> {
        let on = on && !self.is_tree();
        for i in 1..self.joints.len() {
            let parallel = self.joints[i].parallel_to(&self.joints[i - 1]);
            self.joints[i].sum_angles = on && parallel;
        }
        self
    }

    /// Whether some joint turns through the sum of angles of a run
    /// ([`ChainJoint::sum_angles`]): otherwise the summed recursions are the plain ones.
    pub fn has_runs(&self) -> bool {
        self.joints.iter().any(|j| j.sum_angles)
    }

    /// Per joint of a run of revolute joints about parallel axes (its first joint k and those
    /// after it with [`ChainJoint::sum_angles`]), the sine and cosine of `θ_k + ⋯ + θ_i`:
    /// `sin(Σ + θ) = sin Σ cos θ + cos Σ sin θ`, `cos(Σ + θ) = cos Σ cos θ − sin Σ sin θ`.
    /// `None` for a prismatic joint.
    pub fn run_angles(&self) -> Vec<Option<(S, S)>> {
        let mut angles: Vec<Option<(S, S)>> = Vec::with_capacity(self.joints.len());
        for j in &self.joints {
            let (st, ct) = (j.sin_theta, j.cos_theta);
            let angle = match (j.kind, angles.last().copied().flatten()) {
                (JointKind::Prismatic, _) => None,
                (JointKind::Revolute, Some((s, c))) if j.sum_angles => {
                    Some((s * ct + c * st, c * ct - s * st))
                }
                (JointKind::Revolute, _) => Some((st, ct)),
            };
            angles.push(angle);
        }
        angles
    }
}
