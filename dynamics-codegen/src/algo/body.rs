//! A link's inertial parameters about a joint frame's origin ([`Body`]) and how they move:
//! shifted to another origin, `I' = I + m(|p|²1 − p pᵀ) + 2(p·h)1 − p hᵀ − h pᵀ`,
//! `h' = h + m p`; turned, `I' = R I Rᵀ`, `h' = R h`; and carried to the parent joint frame
//! through a joint's turn by θ and twist by α ([`ChainJoint::body_to_parent`]).

use super::chain::is_quarter_turn;
use super::{ChainJoint, Inertial, Mat3, Scalar, V3};
use std::ops::Add;

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

impl<S: Scalar> ChainJoint<S> {
    /// `Rotz(θ) I Rotz(θ)ᵀ`: the first step of [`ChainJoint::body_to_parent`].
    pub fn turned_inertia(&self, i: [S; 6]) -> [S; 6] {
        rotate_inertia(i, self.sin_theta, self.cos_theta, 0, 1)
    }

    /// A body given in J_i expressed about J_{i−1}'s origin in J_{i−1} axes (the antecedent's
    /// in a tree: the row first, then `Rotz(γ)`, then the shift by b along z).
    pub fn body_to_parent(&self, b: &Body<S>) -> Body<S> {
        let Some(pre) = self.pre else {
            return self.body_through_row(b);
        };
        let carried = ChainJoint { pre: None, ..*self }.body_through_row(b);
        let zero = b.mass.zero();
        let turned = Body {
            mass: carried.mass,
            h: pre.turn(carried.h),
            inertia: rotate_inertia(carried.inertia, pre.sin_gamma, pre.cos_gamma, 0, 1),
        };
        turned.moved_by(V3::new(zero, zero, pre.b))
    }

    /// [`ChainJoint::body_to_parent`] through the D-H row alone.
    fn body_through_row(&self, b: &Body<S>) -> Body<S> {
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

/// `R I Rᵀ` for the rotation by the angle of sine `s` and cosine `c` in the plane of axes `u`
/// and `v` (x, y for Rotz; y, z for Rotx) of the symmetric `I = [xx, yy, zz, xy, xz, yz]`:
/// in that plane `I_uu' = c² I_uu − 2cs I_uv + s² I_vv = I_uu − s² (I_uu − I_vv) − 2cs I_uv`,
/// `I_vv' = s² I_uu + 2cs I_uv + c² I_vv = I_uu + I_vv − I_uu'`,
/// `I_uv' = cs (I_uu − I_vv) + (c² − s²) I_uv`; the products with the third axis w turn as a
/// vector.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn rotate_inertia<S: Scalar>(i: [S; 6], s: S, c: S, u: usize, v: usize) -> [S; 6] {
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
