//! A [`Robot`] as a [`Chain`] over any [`Scalar`]: each joint's D-H row with the joint variable
//! substituted (`θ_i = q_i + θ` for a revolute joint, `d_i = q_i + d` for a prismatic one) and
//! its link's inertial parameters, in the robot's D-H convention. Written once for the numeric
//! evaluation and the symbolic trace, which differ only in how a [`Value`] becomes a scalar.

use super::{Chain, DhRow, Inertial, JointKind, Pre, Scalar, V3};
use crate::model::{Convention, Joint, Robot, Value};

/// How a robot's values and joint variables become scalars: numbers for an evaluation at a
/// position, graph nodes for a trace.
pub trait RobotScalars {
    /// The scalar the chain is built over.
    type Scalar: Scalar;

    /// The scalar of `v`.
    fn value(&self, v: &Value) -> Self::Scalar;

    /// `(sin v, cos v)` of a constant angle `v`.
    fn sin_cos(&self, v: &Value) -> (Self::Scalar, Self::Scalar);

    /// The joint variable `q_i` of joint `joint`.
    fn joint_variable(&self, joint: usize) -> Self::Scalar;

    /// `(sin(q_i + offset), cos(q_i + offset))` of revolute joint `joint`.
    fn joint_sin_cos(&mut self, joint: usize, offset: &Value) -> (Self::Scalar, Self::Scalar);

    /// The robot as a chain of joint frames; a tree's joints (modified convention only: the
    /// pipeline refuses a standard table with branches) know their antecedents and `γ`, `b`.
    fn chain(&mut self, robot: &Robot) -> Chain<Self::Scalar> {
        let mut rows = Vec::with_capacity(robot.dof());
        let mut links = Vec::with_capacity(robot.dof());
        for (i, joint) in robot.joints.iter().enumerate() {
            rows.push(self.dh_row(i, joint));
            links.push(self.inertial(joint));
        }
        let mut chain = match robot.convention {
            Convention::Standard => Chain::standard(&rows, &links),
            Convention::Modified => Chain::modified(&rows, &links),
        };
        for (i, joint) in robot.joints.iter().enumerate() {
            if let Some(branch) = &joint.branch {
                let (sin_gamma, cos_gamma) = self.sin_cos(&branch.gamma);
                let b = self.value(&branch.b);
                // Tested on constants only, so that a symbolic γ adds no node.
                let unturned = sin_gamma.is_zero()
                    && cos_gamma.is_constant()
                    && (cos_gamma - cos_gamma.one()).is_zero();
                let turned = !unturned;
                chain.joints[i].parent = robot.parent(i);
                chain.joints[i].pre = (turned || !b.is_zero()).then_some(Pre {
                    sin_gamma,
                    cos_gamma,
                    b,
                });
            }
        }
        chain
    }

    /// Joint `i`'s D-H row with its joint variable substituted.
    fn dh_row(&mut self, i: usize, joint: &Joint) -> DhRow<Self::Scalar> {
        let (sin_theta, cos_theta, d) = match joint.kind {
            JointKind::Revolute => {
                let (s, c) = self.joint_sin_cos(i, &joint.theta);
                (s, c, self.value(&joint.d))
            }
            JointKind::Prismatic => {
                let (s, c) = self.sin_cos(&joint.theta);
                (s, c, self.joint_variable(i) + self.value(&joint.d))
            }
        };
        let (sin_alpha, cos_alpha) = self.sin_cos(&joint.alpha);
        DhRow {
            kind: joint.kind,
            sin_theta,
            cos_theta,
            d,
            a: self.value(&joint.a),
            sin_alpha,
            cos_alpha,
        }
    }

    /// The inertial parameters of `joint`'s link.
    fn inertial(&self, joint: &Joint) -> Inertial<Self::Scalar> {
        let v = |x: &Value| self.value(x);
        Inertial {
            mass: v(&joint.link.mass),
            com: V3::new(
                v(&joint.link.com[0]),
                v(&joint.link.com[1]),
                v(&joint.link.com[2]),
            ),
            inertia: joint.link.inertia.each_ref().map(v),
        }
    }

    /// The gravity acceleration in the base frame.
    fn gravity(&self, robot: &Robot) -> V3<Self::Scalar> {
        let g = &robot.gravity;
        V3::new(self.value(&g[0]), self.value(&g[1]), self.value(&g[2]))
    }
}
