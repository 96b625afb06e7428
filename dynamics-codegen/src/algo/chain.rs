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

/// Joint i of a [`Chain`]: the transform from J_{i−1} to J_i, `Rotx(α) Transx(a) Rotz(θ)
/// Transz(d)`, and link i's body in J_i.
#[derive(Clone, Copy, Debug)]
pub struct ChainJoint<S> {
    /// Joint kind.
    pub kind: JointKind,
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
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        V3::new(v.x, ca * v.y + sa * v.z, ca * v.z - sa * v.y)
    }

    /// `Rotx(α) v`: back from the axes of [`ChainJoint::untwist`] to J_{i−1}'s.
    pub fn twist(&self, v: V3<S>) -> V3<S> {
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        V3::new(v.x, ca * v.y - sa * v.z, sa * v.y + ca * v.z)
    }

    /// `R v`: a vector in J_i axes expressed in J_{i−1} axes.
    pub fn to_parent(&self, v: V3<S>) -> V3<S> {
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        let u = self.to_turned(v);
        V3::new(u.x, ca * u.y - sa * u.z, sa * u.y + ca * u.z)
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
        (self.twist(f), self.twist(n.add(arm.cross(f))))
    }

    /// Whether α is a known multiple of 90°, so that the twist only swaps axes and signs.
    pub(super) fn twist_is_quarter_turn(&self) -> bool {
        is_quarter_turn(self.sin_alpha, self.cos_alpha)
    }

    /// The origin of J_i in J_{i−1}: `(a, −sin α · d, cos α · d)`.
    pub fn offset(&self) -> V3<S> {
        V3::new(self.a, -(self.sin_alpha * self.d), self.cos_alpha * self.d)
    }

    /// The rotation `R` as a matrix.
    pub fn rotation(&self) -> Mat3<S> {
        Mat3::rot_x(self.sin_alpha, self.cos_alpha)
            .mul(&Mat3::rot_z(self.sin_theta, self.cos_theta))
    }

    /// `Rotz(θ) v`: the first step of [`ChainJoint::to_parent`].
    pub fn to_turned(&self, v: V3<S>) -> V3<S> {
        let (st, ct) = (self.sin_theta, self.cos_theta);
        V3::new(ct * v.x - st * v.y, st * v.x + ct * v.y, v.z)
    }
}

/// A serial robot as joint frames; see the module documentation.
#[derive(Clone, Debug)]
pub struct Chain<S> {
    /// The joints, base to tip.
    pub joints: Vec<ChainJoint<S>>,
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
            .map(|(row, link)| {
                let zero = row.d.zero();
                ChainJoint {
                    kind: row.kind,
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

#[cfg(test)]
mod tests {
    use crate::algo::{test_chain, V3};
    use std::ops::Add;

    /// A wrench carried to the parent, the arm crossed before the twist or after it, equals
    /// `(R f, R n + p × R f)` with the full rotation matrix.
    #[test]
    fn carrying_a_wrench() {
        let chain = test_chain(&[0.3, -1.1, 0.25, 2.0, -0.6]);
        let (f, n) = (V3::new(0.4, -1.3, 2.2), V3::new(-0.9, 0.15, 0.6));
        for joint in &chain.joints {
            let r = joint.rotation();
            let rf = r.mul_vec(f);
            let expected = (rf, r.mul_vec(n).add(joint.offset().cross(rf)));
            let carried = joint.wrench_to_parent(f, n);
            for (a, b) in [
                (carried.0.x, expected.0.x),
                (carried.0.y, expected.0.y),
                (carried.0.z, expected.0.z),
                (carried.1.x, expected.1.x),
                (carried.1.y, expected.1.y),
                (carried.1.z, expected.1.z),
            ] {
                assert!((a - b).abs() < 1e-14, "{a} vs {b}");
            }
        }
    }
}
