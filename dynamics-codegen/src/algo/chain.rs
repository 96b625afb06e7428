//! The robot as a chain of joint frames.
//!
//! Standard D-H (Niku, Paul): `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)`; frame i sits
//! at the far end of link i, and joint i moves about z_{i−1}. Because `Rotz` and `Transz`
//! commute, the product `A_1 A_2 ⋯` regroups as
//! `[Rotz(θ_1) Transz(d_1)] [Transx(a_1) Rotx(α_1) Rotz(θ_2) Transz(d_2)] ⋯`, so a frame J_i on
//! the axis of joint i (J_i = frame i of the standard table times `(Transx(a_i) Rotx(α_i))⁻¹`)
//! follows from J_{i−1} by `Rotx(α_{i−1}) Transx(a_{i−1}) Rotz(θ_i) Transz(d_i)`: the modified
//! (Craig) form. The algorithms work in J frames, where joint i's axis is z and its torque is
//! a single component. A link's inertia, given in standard frame i, is carried into J_i exactly.
//!
//! A kinematic tree (Khalil and Kleinfinger) is modified-convention only: joint i's frame is
//! `Rotz(γ_i) Transz(b_i) Rotx(α_i) Transx(a_i) Rotz(θ_i) Transz(d_i)` in the frame of its
//! antecedent `a(i) < i` ([`ChainJoint::parent`], [`Pre`]); in a serial chain `a(i) = i − 1`
//! and γ = b = 0, and every transform below reads as before.

use super::{Body, Mat3, Scalar, V3};
use crate::model::JointKind;
use std::ops::Add;

/// One row of a standard D-H table with the joint variable substituted: for a revolute joint
/// `sin_theta`, `cos_theta` are of `q + offset`, for a prismatic one `d` is `q + offset`.
#[derive(Clone, Copy, Debug)]
pub struct DhRow<S> {
    /// Joint kind.
    pub kind: JointKind,
    /// sin θ_i.
    pub sin_theta: S,
    /// cos θ_i.
    pub cos_theta: S,
    /// d_i.
    pub d: S,
    /// a_i.
    pub a: S,
    /// sin α_i.
    pub sin_alpha: S,
    /// cos α_i.
    pub cos_alpha: S,
}

/// Inertial parameters of a link as a datasheet gives them: mass, centre of mass in link frame
/// i, and the inertia tensor about the centre of mass in the axes of frame i,
/// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` with `Ixy = −∫xy dm` (as URDF).
#[derive(Clone, Copy, Debug)]
pub struct Inertial<S> {
    /// Mass.
    pub mass: S,
    /// Centre of mass.
    pub com: V3<S>,
    /// Inertia tensor about the centre of mass.
    pub inertia: [S; 6],
}

/// The turn γ and offset b about and along the antecedent's z that come before a tree joint's
/// modified D-H row: `Rotz(γ) Transz(b)`.
#[derive(Clone, Copy, Debug)]
pub struct Pre<S> {
    /// sin γ.
    pub sin_gamma: S,
    /// cos γ.
    pub cos_gamma: S,
    /// b.
    pub b: S,
}

impl<S: Scalar> Pre<S> {
    /// `Rotz(γ) v`.
    pub(super) fn turn(&self, v: V3<S>) -> V3<S> {
        let (s, c) = (self.sin_gamma, self.cos_gamma);
        V3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
    }

    /// `Rotz(γ)ᵀ v`.
    pub(super) fn unturn(&self, v: V3<S>) -> V3<S> {
        let (s, c) = (self.sin_gamma, self.cos_gamma);
        V3::new(c * v.x + s * v.y, c * v.y - s * v.x, v.z)
    }

    /// `b z × v`.
    fn arm_cross(&self, v: V3<S>) -> V3<S> {
        V3::new(-(self.b * v.y), self.b * v.x, self.b.zero())
    }
}

/// Joint i of a [`Chain`]: the transform from J_{a(i)} (its antecedent's frame; J_{i−1} in a
/// serial chain) to J_i, `[Rotz(γ) Transz(b)] Rotx(α) Transx(a) Rotz(θ) Transz(d)`, and link
/// i's body in J_i. "Parent" below is the antecedent.
#[derive(Clone, Copy, Debug)]
pub struct ChainJoint<S> {
    /// Joint kind.
    pub kind: JointKind,
    /// The antecedent joint, `None` for the base.
    pub parent: Option<usize>,
    /// `Rotz(γ) Transz(b)` before the row, for a tree joint whose γ or b is not known zero.
    pub pre: Option<Pre<S>>,
    /// sin α (twist about the previous x axis).
    pub sin_alpha: S,
    /// cos α.
    pub cos_alpha: S,
    /// a (length along the previous x axis).
    pub a: S,
    /// sin θ.
    pub sin_theta: S,
    /// cos θ.
    pub cos_theta: S,
    /// d (offset along the new z axis).
    pub d: S,
    /// The link moved by this joint, about J_i's origin.
    pub body: Body<S>,
    /// Whether [`ChainJoint::body_to_parent`] moves a body to the parent's origin before the
    /// twist by α, where the arm is `(a, 0, d)`, rather than after it. Both give the same
    /// body; which takes fewer operations depends on the robot ([`Chain::moving_before_twist`]).
    pub move_before_twist: bool,
    /// Whether this joint's angular rates are computed through the sum of its angle and the
    /// angles of the joints before it that turn about parallel axes (α = 0 between revolute
    /// joints): `ω_i = Rotz(θ_k + ⋯ + θ_i)ᵀ w_k + …` from the vector `w_k` that entered the
    /// first joint k of the run, rather than turned joint by joint, and moments carried back
    /// the same way ([`super::WrenchCarrier`]). Set by [`Chain::summing_angles`]; the intermediate
    /// links' rates are still computed.
    pub sum_angles: bool,
}

impl<S: Scalar> ChainJoint<S> {
    /// `Rᵀ v`: a vector in J_{i−1} axes expressed in J_i axes, with `R = Rotx(α) Rotz(θ)`.
    pub fn to_child(&self, v: V3<S>) -> V3<S> {
        let v = self.pre.map_or(v, |p| p.unturn(v));
        let (sa, ca, st, ct) = (
            self.sin_alpha,
            self.cos_alpha,
            self.sin_theta,
            self.cos_theta,
        );
        let w = V3::new(v.x, ca * v.y + sa * v.z, ca * v.z - sa * v.y);
        V3::new(ct * w.x + st * w.y, ct * w.y - st * w.x, w.z)
    }

    /// `Rotz(θ)ᵀ v`: the second step of [`ChainJoint::to_child`], from the axes of
    /// [`ChainJoint::untwist`].
    pub fn unturn(&self, v: V3<S>) -> V3<S> {
        let (st, ct) = (self.sin_theta, self.cos_theta);
        V3::new(ct * v.x + st * v.y, ct * v.y - st * v.x, v.z)
    }

    /// `Rotx(α)ᵀ v`: a vector in J_{i−1} axes expressed in the axes of J_i before its turn by
    /// θ, which differ from J_i's by a rotation about z.
    pub fn untwist(&self, v: V3<S>) -> V3<S> {
        let v = self.pre.map_or(v, |p| p.unturn(v));
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        V3::new(v.x, ca * v.y + sa * v.z, ca * v.z - sa * v.y)
    }

    /// `Rotx(α) v`: back from the axes of [`ChainJoint::untwist`] to J_{i−1}'s.
    pub fn twist(&self, v: V3<S>) -> V3<S> {
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        let v = V3::new(v.x, ca * v.y - sa * v.z, sa * v.y + ca * v.z);
        self.pre.map_or(v, |p| p.turn(v))
    }

    /// `R v`: a vector in J_i axes expressed in J_{i−1} axes.
    pub fn to_parent(&self, v: V3<S>) -> V3<S> {
        self.twist(self.to_turned(v))
    }

    /// A wrench about J_i's origin in J_i axes (force `f`, moment `n`) carried to J_{i−1}:
    /// `R f` and `R n + p × R f`.
    pub fn wrench_to_parent(&self, f: V3<S>, n: V3<S>) -> (V3<S>, V3<S>) {
        self.wrench_from_turned(self.to_turned(f), self.to_turned(n))
    }

    /// [`ChainJoint::wrench_to_parent`] of a wrench already turned by θ (`Rotz(θ) f`,
    /// `Rotz(θ) n`), or given in the axes of [`ChainJoint::untwist`]. Unless α is a quarter
    /// turn, the moment arm is crossed before the twist, where it reads `(a, 0, d)` rather than
    /// `(a, −sin α d, cos α d)`: two multiplications and two additions fewer.
    pub fn wrench_from_turned(&self, f: V3<S>, n: V3<S>) -> (V3<S>, V3<S>) {
        if self.twist_is_quarter_turn() {
            let rf = self.twist(f);
            return (rf, self.twist(n).add(self.offset().cross(rf)));
        }
        let arm = V3::new(self.a, self.d.zero(), self.d);
        let (rf, rn) = (self.twist(f), self.twist(n.add(arm.cross(f))));
        match self.pre {
            Some(p) => (rf, rn.add(p.arm_cross(rf))),
            None => (rf, rn),
        }
    }

    /// Whether α is a known multiple of 90°, so that the twist only swaps axes and signs.
    pub(super) fn twist_is_quarter_turn(&self) -> bool {
        is_quarter_turn(self.sin_alpha, self.cos_alpha)
    }

    /// The origin of J_i in J_{i−1}: `(a, −sin α · d, cos α · d)`, or in a tree
    /// `Rotz(γ) (a, −sin α · d, cos α · d + b)`.
    pub fn offset(&self) -> V3<S> {
        let o = V3::new(self.a, -(self.sin_alpha * self.d), self.cos_alpha * self.d);
        match self.pre {
            Some(p) => p.turn(V3::new(o.x, o.y, o.z + p.b)),
            None => o,
        }
    }

    /// The rotation `R` as a matrix.
    pub fn rotation(&self) -> Mat3<S> {
        let r = Mat3::rot_x(self.sin_alpha, self.cos_alpha)
            .mul(&Mat3::rot_z(self.sin_theta, self.cos_theta));
        match self.pre {
            Some(p) => Mat3::rot_z(p.sin_gamma, p.cos_gamma).mul(&r),
            None => r,
        }
    }

    /// `Rotz(θ) v`: the first step of [`ChainJoint::to_parent`].
    pub fn to_turned(&self, v: V3<S>) -> V3<S> {
        let (st, ct) = (self.sin_theta, self.cos_theta);
        V3::new(ct * v.x - st * v.y, st * v.x + ct * v.y, v.z)
    }
}

/// A robot (serial or a tree) as joint frames; see the module documentation.
#[derive(Clone, Debug)]
pub struct Chain<S> {
    /// The joints, base to tip, each after its antecedent.
    pub joints: Vec<ChainJoint<S>>,
}

impl<S> Chain<S> {
    /// Joint i's antecedent.
    pub fn parent(&self, i: usize) -> Option<usize> {
        self.joints[i].parent
    }

    /// Whether some joint's antecedent is not the joint before it.
    pub fn is_tree(&self) -> bool {
        (0..self.joints.len()).any(|i| self.parent(i) != i.checked_sub(1))
    }

    /// Whether `a` is `d` or one of its ancestors.
    pub fn supports(&self, a: usize, d: usize) -> bool {
        let mut at = Some(d);
        while let Some(k) = at {
            if k == a {
                return true;
            }
            if k < a {
                return false;
            }
            at = self.parent(k);
        }
        false
    }
}

impl<S: Scalar> Chain<S> {
    /// The chain of a standard D-H table. `rows` and `links` have one entry per joint.
    pub fn standard(rows: &[DhRow<S>], links: &[Inertial<S>]) -> Chain<S> {
        let joints = rows
            .iter()
            .zip(links)
            .enumerate()
            .map(|(i, (row, link))| {
                let zero = row.d.zero();
                let (sa, ca, a) = match i.checked_sub(1).map(|p| &rows[p]) {
                    Some(prev) => (prev.sin_alpha, prev.cos_alpha, prev.a),
                    None => (zero, zero.one(), zero),
                };
                ChainJoint {
                    kind: row.kind,
                    parent: i.checked_sub(1),
                    pre: None,
                    sin_alpha: sa,
                    cos_alpha: ca,
                    a,
                    sin_theta: row.sin_theta,
                    cos_theta: row.cos_theta,
                    d: row.d,
                    body: Body::from_inertial(link, row.a, row.sin_alpha, row.cos_alpha),
                    move_before_twist: false,
                    sum_angles: false,
                }
            })
            .collect();
        Chain { joints }
    }

    /// The chain of a modified (Craig) D-H table, whose row i holds `a_{i−1}`, `α_{i−1}`,
    /// `θ_i`, `d_i`; link frames are the joint frames.
    pub fn modified(rows: &[DhRow<S>], links: &[Inertial<S>]) -> Chain<S> {
        let joints = rows
            .iter()
            .zip(links)
            .enumerate()
            .map(|(i, (row, link))| {
                let zero = row.d.zero();
                ChainJoint {
                    kind: row.kind,
                    parent: i.checked_sub(1),
                    pre: None,
                    sin_alpha: row.sin_alpha,
                    cos_alpha: row.cos_alpha,
                    a: row.a,
                    sin_theta: row.sin_theta,
                    cos_theta: row.cos_theta,
                    d: row.d,
                    body: Body::from_inertial(link, zero, zero, zero.one()),
                    move_before_twist: false,
                    sum_angles: false,
                }
            })
            .collect();
        Chain { joints }
    }
}

impl<S: Scalar> Chain<S> {
    /// The same chain with [`ChainJoint::move_before_twist`] set to `on` for every joint.
    #[must_use]
    pub fn moving_before_twist(mut self, on: bool) -> Chain<S> {
        for j in &mut self.joints {
            j.move_before_twist = on;
        }
        self
    }
}

/// Whether the angle of sine `s` and cosine `c` is a known multiple of 90°: a rotation by it
/// swaps axes and signs, and every product with its sine or cosine folds.
pub(super) fn is_quarter_turn<S: Scalar>(s: S, c: S) -> bool {
    s.is_constant() && c.is_constant() && (s.is_zero() || c.is_zero())
}
