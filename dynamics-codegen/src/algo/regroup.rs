//! Regrouping of inertial parameters: the parts of a link's inertia that its joint cannot
//! move are carried onto the link before it, which leaves the dynamics unchanged and the
//! traced equations shorter.

use super::{Body, Chain, ChainJoint, JointKind, Scalar, V3};

impl<S: Scalar> Chain<S> {
    /// The same robot with inertial parameters regrouped onto fewer links, leaving `M`, `τ`,
    /// `g` and the energies exactly unchanged (in the spirit of Khalil and Gautier's base
    /// parameters):
    ///
    /// * revolute joint j: the part of link j that is symmetric about joint j's axis (its mass,
    ///   the first moment along z, and an inertia `diag(Iyy, Iyy, 0)`) looks the same from link
    ///   j−1 whatever q_j, so it moves onto link j−1; link j keeps `Ixx − Iyy`, `Izz`, the
    ///   products and `h_x`, `h_y`;
    /// * prismatic joint j: link j turns with link j−1, so its rotational inertia moves onto
    ///   link j−1; link j keeps its mass and first moment.
    ///
    /// Joints on the base are left alone: their symmetric part would move onto the base, which
    /// changes the potential energy by a constant. In a tree "link j−1" is the antecedent's
    /// link, carried onto through γ and b too; the joints are taken from the last, so that a
    /// link has received its children's parts before it hands its own on.
    #[must_use]
    pub fn regrouped(&self) -> Chain<S> {
        let mut joints = self.joints.clone();
        for j in (1..joints.len()).rev() {
            let joint = joints[j];
            let Some(parent) = joint.parent else {
                continue;
            };
            let b = joint.body;
            let zero = b.mass.zero();
            let (moved, kept, through) = match joint.kind {
                JointKind::Revolute => {
                    let [xx, yy, zz, xy, xz, yz] = b.inertia;
                    let moved = Body {
                        mass: b.mass,
                        h: V3::new(zero, zero, b.h.z),
                        inertia: [yy, yy, zero, zero, zero, zero],
                    };
                    let kept = Body {
                        mass: zero,
                        h: V3::new(b.h.x, b.h.y, zero),
                        inertia: [xx - yy, zero, zz, xy, xz, yz],
                    };
                    // The moved part is symmetric about z: any θ carries it the same way.
                    let through = ChainJoint {
                        sin_theta: zero,
                        cos_theta: zero.one(),
                        ..joint
                    };
                    (moved, kept, through)
                }
                JointKind::Prismatic => {
                    let moved = Body {
                        mass: zero,
                        h: V3::zero(zero),
                        inertia: b.inertia,
                    };
                    let kept = Body {
                        mass: b.mass,
                        h: b.h,
                        inertia: [zero; 6],
                    };
                    (moved, kept, joint)
                }
            };
            joints[j].body = kept;
            let carried = through.body_to_parent(&moved);
            joints[parent].body = joints[parent].body.add(&carried);
        }
        Chain { joints }
    }
}
