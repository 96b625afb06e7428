//! Recursive Newton-Euler (Luh, Walker, Paul): inverse dynamics
//! `tau = M(q) qdd + C(q, qd) qd + g(q)` in O(n).
//!
//! Forward, in joint frames, from each joint's antecedent `a = a(i)` (`i − 1` in a chain):
//! `ω_i = Rᵀω_a + q̇_i z`, `ω̇_i = Rᵀω̇_a + Rᵀω_a × q̇_i z + q̈_i z`,
//! `v̇_i = Rᵀ(v̇_a + ω̇_a × p_i + ω_a × (ω_a × p_i))` (plus `2ω_i × ḋ z + d̈ z` for a prismatic
//! joint), with `v̇_0 = −gravity` at the base. With first moments `h = m c`:
//! `F_i = m v̇_i + ω̇_i × h + ω_i × (ω_i × h)`, `N_i = I ω̇_i + ω_i × I ω_i + h × v̇_i`, the first two
//! terms of `N_i` read off Khalil's `U = [ω̇]× + [ω]×[ω]×`, which `F_i` and `v̇_{i+1}` use too.
//! Backward, over the children c of i (joints whose antecedent is i; `i + 1` in a chain):
//! `f_i = F_i + Σ R_c f_c`, `n_i = N_i + Σ (R_c n_c + p_c × R_c f_c)`, and
//! `tau_i = n_i · z` (revolute) or `f_i · z` (prismatic). Setting `qdd = 0` and gravity to zero
//! gives `C(q, qd) qd`; `qd = qdd = 0` gives `g(q)`; column j of `M` is `qd = 0`, `qdd = e_j`
//! without gravity.
//!
//! A last link that is axially symmetric about its revolute joint (after regrouping this is
//! often a flange or tool with only `Izz` left) is computed in the axes of its joint frame
//! before the turn by θ: its equations read the same there, and neither its velocities nor its
//! moment need that turn (PUMA 560: no sine or cosine of q6 in `τ` at all).
//!
//! Joints about parallel axes (α = 0 between revolute joints k, …, i) turn about the same z, so
//! `J_{k−1}` to `J_i` turns by `Rotz(θ_k + ⋯ + θ_i)`. With [`super::ChainJoint::sum_angles`],
//! `ω_i = Rotz(Σθ)ᵀ w_k + (q̇_k + ⋯ + q̇_i) z` and
//! `ω̇_i = Rotz(Σθ)ᵀ ẇ_k + (q̇_k + ⋯ + q̇_i) ω_i × z + (q̈_k + ⋯ + q̈_i) z` from the vectors `w_k`,
//! `ẇ_k` that entered joint k (in its axes before its turn), and each link's moment across z turns back to joint k in one step: where
//! `w_k` is sparse (PUMA 560's `(0, q̇_1, 0)`), one turn costs what two did. The sine and
//! cosine of the sum cost 3 operations each; derive keeps whichever way is cheaper.

use super::{Chain, JointKind, Scalar, WrenchCarrier, V3};
use std::ops::{Add, Neg};

/// Joint torques of `chain` moving with velocities `qd` and accelerations `qdd` under `gravity`
/// (the gravity acceleration in the base frame). Actuator inertia and springs are not included.
pub fn rnea<S: Scalar>(chain: &Chain<S>, qd: &[S], qdd: &[S], gravity: V3<S>) -> Vec<S> {
    let zero = gravity.x.zero();
    // The base does not move.
    let base = BaseMotion {
        w: V3::zero(zero),
        wd: V3::zero(zero),
        vd: gravity.neg(),
    };
    rnea_from(chain, &base, qd, qdd, false).0
}

/// A wrench `(f, n)`: force, and moment about a frame's origin, in its axes.
pub type Wrench<S> = (V3<S>, V3<S>);

/// The motion of frame 0 (the chain's base), in its axes: angular velocity `w`, angular
/// acceleration `wd`, and the acceleration of its origin less gravity `vd`.
pub struct BaseMotion<S> {
    /// ω.
    pub w: V3<S>,
    /// ω̇.
    pub wd: V3<S>,
    /// The origin's classical acceleration minus gravity.
    pub vd: V3<S>,
}

/// [`rnea`] on a chain whose base moves as `base`; with `carry_root`, also the wrench
/// `(f, n)` the joints on the base exert on it at frame 0's origin, in its axes (a floating
/// base's share, [`super::floating_rnea`]). Without it no node is added for that wrench.
pub fn rnea_from<S: Scalar>(
    chain: &Chain<S>,
    base: &BaseMotion<S>,
    qd: &[S],
    qdd: &[S],
    carry_root: bool,
) -> (Vec<S>, Option<Wrench<S>>) {
    let n = chain.joints.len();
    let zero = base.w.x.zero();
    let base = Link {
        w: base.w,
        wd: base.wd,
        vd: base.vd,
        u: Rates::new(base.w, base.wd),
    };
    let mut links: Vec<Link<S>> = Vec::with_capacity(n);
    let mut forces = Vec::with_capacity(n);
    let unturned = unturned_last(chain);
    // The rates that entered the first joint of the current run of parallel revolute joints
    // (untwisted, before its turn), and per joint the sine and cosine of the run's angle.
    let mut run: Option<(V3<S>, V3<S>)> = None;
    let angles = chain.run_angles();
    for (i, j) in chain.joints.iter().enumerate() {
        let parent = j.parent.map_or(&base, |p| &links[p]);
        let (mut w, mut wd) = (parent.w, parent.wd);
        let p = j.offset();
        let vd_parent = parent.vd.add(parent.u.mul(p));
        let to_child = |v| {
            if unturned == Some(i) {
                j.untwist(v)
            } else {
                j.to_child(v)
            }
        };
        let mut vd = to_child(vd_parent);
        let summed = match (run, angles[i]) {
            (Some(entered), Some(angle)) if j.sum_angles && unturned != Some(i) => {
                Some((entered, angle))
            }
            _ => None,
        };
        match (j.kind, summed) {
            (JointKind::Revolute, Some(((w_k, wd_k), (s, c)))) => {
                // Rotz(Σθ)ᵀ; the z components add up as they go.
                let turned_back = |v: V3<S>| V3::new(c * v.x + s * v.y, c * v.y - s * v.x, v.z);
                let (w_in, wd_in) = (turned_back(w_k), turned_back(wd_k));
                let next = V3::new(w_in.x, w_in.y, w.z + qd[i]);
                // (q̇_k + ⋯ + q̇_i) ω_i × z, the sum being ω_i's z less what entered the run.
                let c = next.cross_z(next.z - w_k.z);
                wd = V3::new(wd_in.x + c.x, wd_in.y + c.y, wd.z + qdd[i]);
                w = next;
            }
            (JointKind::Revolute, None) => {
                run = (unturned != Some(i)).then(|| (j.untwist(w), j.untwist(wd)));
                let (w_in, wd_in) = (to_child(w), to_child(wd));
                w = V3::new(w_in.x, w_in.y, w_in.z + qd[i]);
                let c = w_in.cross_z(qd[i]);
                wd = V3::new(wd_in.x + c.x, wd_in.y + c.y, wd_in.z + qdd[i]);
            }
            (JointKind::Prismatic, _) => {
                run = None;
                w = to_child(w);
                wd = to_child(wd);
                let c = w.cross_z(qd[i] + qd[i]);
                vd = V3::new(vd.x + c.x, vd.y + c.y, vd.z + qdd[i]);
            }
        }
        let b = &j.body;
        let u = Rates::new(w, wd);
        let f = vd.scale(b.mass).add(u.mul(b.h));
        let nn = u.inertial_moment(b.inertia).add(b.h.cross(vd));
        forces.push((f, nn));
        links.push(Link { w, wd, vd, u });
    }
    backward(chain, forces, unturned, zero, carry_root)
}

/// Newton-Euler's backward pass: from the last joint down, each link's total wrench (its own
/// and its children's) gives its joint's torque and is added to its antecedent's.
fn backward<S: Scalar>(
    chain: &Chain<S>,
    mut forces: Vec<(V3<S>, V3<S>)>,
    unturned: Option<usize>,
    zero: S,
    carry_root: bool,
) -> (Vec<S>, Option<Wrench<S>>) {
    let n = chain.joints.len();
    let mut tau = vec![zero; n];
    let mut root: Option<Wrench<S>> = carry_root.then(|| (V3::zero(zero), V3::zero(zero)));
    let mut carrier = WrenchCarrier::new(chain);
    for i in (0..n).rev() {
        let (f, nn) = forces[i];
        tau[i] = match chain.joints[i].kind {
            JointKind::Revolute => nn.z,
            JointKind::Prismatic => f.z,
        };
        let parent = chain.parent(i);
        if parent.is_none() && root.is_none() {
            continue;
        }
        let (rf, rn) = if unturned == Some(i) {
            chain.joints[i].wrench_from_turned(f, nn)
        } else {
            carrier.to_parent(i, f, nn)
        };
        if let Some(p) = parent {
            forces[p] = (forces[p].0.add(rf), forces[p].1.add(rn));
        } else if let Some((f0, n0)) = root {
            root = Some((f0.add(rf), n0.add(rn)));
        }
    }
    (tau, root)
}

/// A link's rates in its joint frame, which its children's recursions start from.
struct Link<S> {
    w: V3<S>,
    wd: V3<S>,
    vd: V3<S>,
    u: Rates<S>,
}

/// The last joint, if it is revolute and its link axially symmetric about it: that link is
/// computed in unturned axes.
fn unturned_last<S: Scalar>(chain: &Chain<S>) -> Option<usize> {
    let last = chain.joints.len().checked_sub(1)?;
    let j = &chain.joints[last];
    (j.kind == JointKind::Revolute && j.body.is_axially_symmetric()).then_some(last)
}

/// A link's angular velocity `ω` and acceleration `ω̇` as Khalil writes them: the products
/// `ω_i ω_j` and `U = [ω̇]× + [ω]×[ω]×`, which the link's force, its moment and the next
/// link's acceleration all read.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Rates<S> {
    /// `ω̇`.
    wd: V3<S>,
    /// `[ω_x², ω_y², ω_z², ω_x ω_y, ω_x ω_z, ω_y ω_z]`.
    products: [S; 6],
    /// `U`, rows first.
    u: [[S; 3]; 3],
}

impl<S: Scalar> Rates<S> {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn new(w: V3<S>, wd: V3<S>) -> Rates<S> {
        let (xx, yy, zz) = (w.x * w.x, w.y * w.y, w.z * w.z);
        let (xy, xz, yz) = (w.x * w.y, w.x * w.z, w.y * w.z);
        let u = [
            [-(yy + zz), xy - wd.z, xz + wd.y],
            [xy + wd.z, -(xx + zz), yz - wd.x],
            [xz - wd.y, yz + wd.x, -(xx + yy)],
        ];
        Rates {
            wd,
            products: [xx, yy, zz, xy, xz, yz],
            u,
        }
    }

    /// `U x = ω̇ × x + ω × (ω × x)`: the acceleration of the point `x` of the link relative to
    /// its origin (the centre of mass and the next origin share the products).
    fn mul(&self, x: V3<S>) -> V3<S> {
        let u = &self.u;
        V3::new(
            u[0][0] * x.x + u[0][1] * x.y + u[0][2] * x.z,
            u[1][0] * x.x + u[1][1] * x.y + u[1][2] * x.z,
            u[2][0] * x.x + u[2][1] * x.y + u[2][2] * x.z,
        )
    }

    /// `I ω̇ + ω × I ω` for `I = [a, b, c, d, e, f]` (`[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`), read off
    /// the entries of `U` rather than through `I ω`: its x component is
    /// `a ω̇_x − d U_zx + e U_yx + f (ω_y² − ω_z²) + (c − b) ω_y ω_z`, and y and z follow by
    /// turning the axes. 30 operations against 42, the off-diagonal `U_ij` being shared with
    /// the forces.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn inertial_moment(&self, inertia: [S; 6]) -> V3<S> {
        let [xx, yy, zz, xy, xz, yz] = self.products;
        let (u, wd) = (&self.u, self.wd);
        let [a, b, c, d, e, f] = inertia;
        V3::new(
            a * wd.x - d * u[2][0] + e * u[1][0] + f * (yy - zz) + (c - b) * yz,
            b * wd.y + d * u[2][1] - f * u[0][1] + e * (zz - xx) + (a - c) * xz,
            c * wd.z - e * u[1][2] + f * u[0][2] + d * (xx - yy) + (b - a) * xy,
        )
    }
}
