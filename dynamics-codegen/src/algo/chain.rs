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

use super::{Mat3, Scalar, V3};
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

/// Inertial parameters about a joint frame's origin, linear in the parameters: mass `m`, first
/// moment `h = m c`, inertia tensor `I_O = I_C + m(cᵀc·1 − c cᵀ)`.
#[derive(Clone, Copy, Debug)]
pub struct Body<S> {
    /// Mass.
    pub mass: S,
    /// First moment of mass about the origin.
    pub h: V3<S>,
    /// Inertia tensor about the origin, `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`.
    pub inertia: [S; 6],
}

impl<S: Scalar> Body<S> {
    /// The body of a link whose frame is `(shift_x, 0, 0)` and `Rotx(α)` from the joint frame.
    pub fn from_inertial(link: &Inertial<S>, shift_x: S, sin_alpha: S, cos_alpha: S) -> Body<S> {
        let rot = Mat3::rot_x(sin_alpha, cos_alpha);
        let c = rot.mul_vec(link.com);
        let c = V3::new(c.x + shift_x, c.y, c.z);
        let ic = Mat3::symmetric(link.inertia).congruence(&rot);
        let m = link.mass;
        let (mx, my, mz) = (m * c.x, m * c.y, m * c.z);
        Body {
            mass: m,
            h: V3::new(mx, my, mz),
            inertia: [
                ic[0] + (my * c.y + mz * c.z),
                ic[1] + (mx * c.x + mz * c.z),
                ic[2] + (mx * c.x + my * c.y),
                ic[3] - mx * c.y,
                ic[4] - mx * c.z,
                ic[5] - my * c.z,
            ],
        }
    }

    /// Whether the body looks the same after any rotation about z: `Ixx = Iyy`, no products of
    /// inertia, first moment on the axis. Known exactly: a symbolic parameter is not assumed
    /// to be zero.
    pub fn is_axially_symmetric(&self) -> bool {
        let [xx, yy, _, xy, xz, yz] = self.inertia;
        (xx - yy).is_zero()
            && xy.is_zero()
            && xz.is_zero()
            && yz.is_zero()
            && self.h.x.is_zero()
            && self.h.y.is_zero()
    }

    /// `I_O · w`.
    pub fn inertia_mul(&self, w: V3<S>) -> V3<S> {
        Mat3::symmetric(self.inertia).mul_vec(w)
    }

    /// The body about the point `−p` (same axes): seen from a frame whose origin is the
    /// body's origin minus `p`. `I' = I + m(|p|²1 − p pᵀ) + 2(p·h)1 − p hᵀ − h pᵀ`,
    /// `h' = h + m p`.
    #[must_use]
    pub fn moved_by(&self, p: V3<S>) -> Body<S> {
        let (m, h, i) = (self.mass, self.h, self.inertia);
        let mp = p.scale(m);
        let (px, py, pz) = (p.x, p.y, p.z);
        let xx = mp.y * py + mp.z * pz;
        let yy = mp.x * px + mp.z * pz;
        let zz = mp.x * px + mp.y * py;
        let (phx, phy, phz) = (px * h.x, py * h.y, pz * h.z);
        Body {
            mass: m,
            h: h.add(mp),
            inertia: [
                i[0] + xx + (phy + phz) + (phy + phz),
                i[1] + yy + (phx + phz) + (phx + phz),
                i[2] + zz + (phx + phy) + (phx + phy),
                i[3] - mp.x * py - (px * h.y + h.x * py),
                i[4] - mp.x * pz - (px * h.z + h.x * pz),
                i[5] - mp.y * pz - (py * h.z + h.y * pz),
            ],
        }
    }

    /// `self + o` (both about the same origin, same axes).
    #[must_use]
    pub fn add(&self, o: &Body<S>) -> Body<S> {
        let i = &self.inertia;
        let j = &o.inertia;
        Body {
            mass: self.mass + o.mass,
            h: self.h.add(o.h),
            inertia: [
                i[0] + j[0],
                i[1] + j[1],
                i[2] + j[2],
                i[3] + j[3],
                i[4] + j[4],
                i[5] + j[5],
            ],
        }
    }
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
    /// the same way ([`WrenchCarrier`]). Set by [`Chain::summing_angles`]; the intermediate
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

    /// Whether joint i turns about an axis parallel to joint i−1's, both revolute: α = 0
    /// exactly, so that J_{i−2} to J_i is `Rotx(α_{i−2}) Rotz(θ_{i−1} + θ_i)` up to a shift.
    pub fn parallel_to(&self, previous: &ChainJoint<S>) -> bool {
        self.kind == JointKind::Revolute
            && previous.kind == JointKind::Revolute
            && self.sin_alpha.is_zero()
            && (self.cos_alpha - self.cos_alpha.one()).is_zero()
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
    fn twist_is_quarter_turn(&self) -> bool {
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

    /// `Rotz(θ) I Rotz(θ)ᵀ`: the first step of [`ChainJoint::body_to_parent`].
    pub fn turned_inertia(&self, i: [S; 6]) -> [S; 6] {
        rotate_inertia(i, self.sin_theta, self.cos_theta, 0, 1)
    }

    /// A body given in J_i expressed about J_{i−1}'s origin in J_{i−1} axes.
    pub fn body_to_parent(&self, b: &Body<S>) -> Body<S> {
        if !self.move_before_twist || self.twist_is_quarter_turn() {
            let turned = Body {
                mass: b.mass,
                h: self.to_parent(b.h),
                inertia: rotate_inertia(
                    self.turned_inertia(b.inertia),
                    self.sin_alpha,
                    self.cos_alpha,
                    1,
                    2,
                ),
            };
            return turned.moved_by(self.offset());
        }
        let turned = Body {
            mass: b.mass,
            h: self.to_turned(b.h),
            inertia: self.turned_inertia(b.inertia),
        };
        let moved = turned.moved_by(V3::new(self.a, self.d.zero(), self.d));
        Body {
            mass: moved.mass,
            h: self.twist(moved.h),
            inertia: rotate_inertia(moved.inertia, self.sin_alpha, self.cos_alpha, 1, 2),
        }
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

    /// The same chain with [`ChainJoint::sum_angles`] set to `on` for every joint parallel to
    /// the one before it.
    #[must_use]
    pub fn summing_angles(mut self, on: bool) -> Chain<S> {
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
    /// Joint 1 is left alone: its symmetric part would move onto the base, which changes the
    /// potential energy by a constant.
    #[must_use]
    pub fn regrouped(&self) -> Chain<S> {
        let mut joints = self.joints.clone();
        for j in (1..joints.len()).rev() {
            let joint = joints[j];
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
            joints[j - 1].body = joints[j - 1].body.add(&carried);
        }
        Chain { joints }
    }
}

/// Whether the angle of sine `s` and cosine `c` is a known multiple of 90°: a rotation by it
/// swaps axes and signs, and every product with its sine or cosine folds.
fn is_quarter_turn<S: Scalar>(s: S, c: S) -> bool {
    s.is_constant() && c.is_constant() && (s.is_zero() || c.is_zero())
}

/// `R I Rᵀ` for the rotation by the angle of sine `s` and cosine `c` in the plane of axes `u`
/// and `v` (x, y for Rotz; y, z for Rotx) of the symmetric `I = [xx, yy, zz, xy, xz, yz]`:
/// in that plane `I_uu' = c² I_uu − 2cs I_uv + s² I_vv = I_uu − s² (I_uu − I_vv) − 2cs I_uv`,
/// `I_vv' = s² I_uu + 2cs I_uv + c² I_vv = I_uu + I_vv − I_uu'`,
/// `I_uv' = cs (I_uu − I_vv) + (c² − s²) I_uv`; the products with the third axis w turn as a
/// vector.
fn rotate_inertia<S: Scalar>(i: [S; 6], s: S, c: S, u: usize, v: usize) -> [S; 6] {
    // Index of the product of two axes in [xx, yy, zz, xy, xz, yz].
    let product = |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => 3,
        (0, 2) => 4,
        _ => 5,
    };
    let w = 3 - u - v;
    let (uu, vv, uv) = (i[u], i[v], i[product(u, v)]);
    let (uw, vw) = (i[product(u, w)], i[product(v, w)]);
    let (cc, ss, cs) = (c * c, s * s, c * s);
    let difference = uu - vv;
    // A quarter turn (or none) folds the direct forms to a swap; any other angle takes fewer
    // multiplications through the difference `I_uu − I_vv`, which `I_uv'` needs anyway, and
    // the trace.
    let (uu2, vv2) = if is_quarter_turn(s, c) {
        (
            cc * uu - (cs * uv + cs * uv) + ss * vv,
            ss * uu + (cs * uv + cs * uv) + cc * vv,
        )
    } else {
        let uu2 = uu - ss * difference - (cs + cs) * uv;
        (uu2, uu + vv - uu2)
    };
    let uv2 = cs * difference + (cc - ss) * uv;
    let mut out = i;
    out[u] = uu2;
    out[v] = vv2;
    out[product(u, v)] = uv2;
    out[product(u, w)] = c * uw - s * vw;
    out[product(v, w)] = s * uw + c * vw;
    out
}

#[cfg(test)]
mod tests {
    use super::{rotate_inertia, Mat3};
    use crate::algo::{test_chain, V3};
    use std::ops::Add;

    /// A body carried to the parent is the same moved before the twist or after it, and its
    /// first moment is `R h + m p` (the inertia is checked end to end, by the derivative test
    /// of `crba` and the reference data).
    #[test]
    fn carrying_a_body() {
        let chain = test_chain(&[0.3, -1.1, 0.25, 2.0, -0.6]);
        for joint in &chain.joints[1..] {
            let b = &joint.body;
            let mut before = *joint;
            before.move_before_twist = true;
            let (x, y) = (joint.body_to_parent(b), before.body_to_parent(b));
            let r = joint.rotation();
            let h = r.mul_vec(b.h).add(joint.offset().scale(b.mass));
            for (u, v) in [
                (x.h.x, y.h.x),
                (x.h.y, y.h.y),
                (x.h.z, y.h.z),
                (x.h.x, h.x),
                (x.h.y, h.y),
                (x.h.z, h.z),
            ] {
                assert!((u - v).abs() < 1e-14, "{u} vs {v}");
            }
            for (u, v) in x.inertia.iter().zip(y.inertia) {
                assert!((u - v).abs() < 1e-14, "{:?} vs {:?}", x.inertia, y.inertia);
            }
        }
    }

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

    /// The plane-rotation formulas agree with `R I Rᵀ` of the full matrices, for Rotz then
    /// Rotx (the order of `ChainJoint::rotation`).
    #[test]
    fn rotating_an_inertia_tensor() {
        let i = [0.7, 0.5, 0.4, -0.05, 0.08, 0.03];
        for (theta, alpha) in [
            (0.3f64, -1.2f64),
            (2.5, 0.0),
            (-1.1, std::f64::consts::FRAC_PI_2),
        ] {
            let (st, ct) = theta.sin_cos();
            let (sa, ca) = alpha.sin_cos();
            let by_planes = rotate_inertia(rotate_inertia(i, st, ct, 0, 1), sa, ca, 1, 2);
            let r = Mat3::rot_x(sa, ca).mul(&Mat3::rot_z(st, ct));
            let full = Mat3::symmetric(i).congruence(&r);
            for (a, b) in by_planes.iter().zip(full) {
                assert!((a - b).abs() < 1e-15, "{by_planes:?} vs {full:?}");
            }
        }
    }
}
