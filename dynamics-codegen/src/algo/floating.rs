//! A tree on a free-flying base (Pinocchio's free flyer), written once over the scalar.
//!
//! The configuration is `q = [x, y, z, qx, qy, qz, qw, q_1 … q_n]` (`n + 7` numbers: the base
//! origin in the world and a unit quaternion of its orientation `R`), the velocity
//! `v = [v, ω, q̇_1 … q̇_n]` (`n + 6`: the base origin's velocity and the base's angular
//! velocity, both in base axes), the acceleration `a` its time derivative in the same
//! coordinates, and the first six rows of `τ` the wrench `[f, n]` on the base in base axes, its
//! moment about the base origin.
//!
//! The quaternion enters through `R`, a polynomial of its components (Eigen's, so
//! Pinocchio's):
//! `R = [[1 − 2(y² + z²), 2(xy − zw), 2(xz + yw)], [2(xy + zw), 1 − 2(x² + z²), 2(yz − xw)],
//! [2(xz − yw), 2(yz + xw), 1 − 2(x² + y²)]]`. It is not normalised: a quaternion that is
//! not unit gives a matrix that is not a rotation, as in Pinocchio. Only gravity reads it, as
//! `g_b = Rᵀ g` in base axes; the base position reads nowhere. So `M` does not depend on the
//! base pose at all.
//!
//! Newton-Euler starts from the base's own motion: the base body (the root link and what is
//! fixed to it, about the base origin: mass `m`, first moment `h`, inertia `I`) has
//! `ω`, `ω̇` and the origin's classical acceleration less gravity `a_b = v̇ + ω × v − g_b`,
//! and exerts `F = m a_b + ω̇ × h + ω × (ω × h)`, `N = I ω̇ + ω × I ω + h × a_b`. The chain's
//! frame 0 sits at `(R_0, p_0)` in the base frame, moving with `R_0ᵀ ω`, `R_0ᵀ ω̇` and
//! `R_0ᵀ (a_b + ω̇ × p_0 + ω × (ω × p_0))` ([`super::BaseMotion`]); the joints' recursion
//! returns the wrench `(f_0, n_0)` they put on frame 0, and the base's rows are
//! `f = F + R_0 f_0`, `n = N + R_0 n_0 + p_0 × R_0 f_0`.
//!
//! The composite rigid body algorithm gives `M`: the joints' block is the fixed base's; the
//! coupling column of joint i is the wrench of its composite body `Ic_i` under a unit `q̈_i`,
//! carried to the base frame as above; the base's 6×6 block is the composite of the whole
//! robot about the base origin, `[[m 1, −[h]×], [[h]×, I]]`.

use super::crba::{composites, wrench};
use super::rnea::{rnea_from, BaseMotion};
use super::{crba, Body, Chain, Inertial, Mat3, Scalar, WrenchCarrier, V3};
use std::ops::Add;

/// The free-flying base of a chain: its own body and where the chain's frame 0 sits on it.
#[derive(Clone, Copy, Debug)]
pub struct FloatingBase<S> {
    /// The base body about the base origin, in base axes.
    pub body: Body<S>,
    /// `R_0`: frame 0's axes in base axes.
    pub rotation: Mat3<S>,
    /// `p_0`: frame 0's origin in the base frame.
    pub origin: V3<S>,
}

impl<S: Scalar> FloatingBase<S> {
    /// The base of a body with the inertial parameters `link` (centre of mass and inertia in
    /// base axes), frame 0 at `(rotation, origin)`.
    pub fn new(link: &Inertial<S>, rotation: Mat3<S>, origin: V3<S>) -> FloatingBase<S> {
        let zero = link.mass.zero();
        FloatingBase {
            body: Body::from_inertial(link, zero, zero, zero.one()),
            rotation,
            origin,
        }
    }

    /// A wrench at frame 0 in its axes, about the base origin in base axes.
    pub(super) fn wrench_to_base(&self, f: V3<S>, n: V3<S>) -> (V3<S>, V3<S>) {
        let f = self.rotation.mul_vec(f);
        let n = self.rotation.mul_vec(n).add(self.origin.cross(f));
        (f, n)
    }

    /// A body about frame 0's origin in its axes, about the base origin in base axes.
    fn body_to_base(&self, b: &Body<S>) -> Body<S> {
        let turned = Body {
            mass: b.mass,
            h: self.rotation.mul_vec(b.h),
            inertia: Mat3::symmetric(b.inertia).congruence(&self.rotation),
        };
        turned.moved_by(self.origin)
    }
}

/// The rotation matrix of the quaternion `[x, y, z, w]`, polynomial in its components (see
/// the module's doc): a rotation only for a unit quaternion.
pub fn quaternion_rotation<S: Scalar>([x, y, z, w]: [S; 4]) -> Mat3<S> {
    let one = x.one();
    let two = |a: S| a + a;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, xz, yz) = (x * y, x * z, y * z);
    let (xw, yw, zw) = (x * w, y * w, z * w);
    Mat3 {
        m: [
            [one - two(yy + zz), two(xy - zw), two(xz + yw)],
            [two(xy + zw), one - two(xx + zz), two(yz - xw)],
            [two(xz - yw), two(yz + xw), one - two(xx + yy)],
        ],
    }
}

/// Inverse dynamics on a floating base: `τ = M(q) a + h(q, v)`, `6 + n` rows (the base's
/// wrench, then the joints'), for the base orientation `quaternion`, velocity `v` and
/// acceleration `a` (`6 + n` each, as in the module's doc), under `gravity` in world axes.
/// Actuator inertia and springs are not included.
pub fn floating_rnea<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    quaternion: [S; 4],
    v: &[S],
    a: &[S],
    gravity: V3<S>,
) -> Vec<S> {
    let vector = |x: &[S], k: usize| V3::new(x[k], x[k + 1], x[k + 2]);
    let (lin, w) = (vector(v, 0), vector(v, 3));
    let (lin_d, wd) = (vector(a, 0), vector(a, 3));
    let g_base = quaternion_rotation(quaternion).tr_mul_vec(gravity);
    let ab = lin_d.add(w.cross(lin)) - g_base;
    let body = &base.body;
    let spin = |x: V3<S>| wd.cross(x).add(w.cross(w.cross(x)));
    let force = ab.scale(body.mass).add(spin(body.h));
    let moment = body
        .inertia_mul(wd)
        .add(w.cross(body.inertia_mul(w)))
        .add(body.h.cross(ab));
    let r0 = &base.rotation;
    let motion = BaseMotion {
        w: r0.tr_mul_vec(w),
        wd: r0.tr_mul_vec(wd),
        vd: r0.tr_mul_vec(ab.add(spin(base.origin))),
    };
    let (joints, root) = rnea_from(chain, &motion, &v[6..], &a[6..], true);
    let (f0, n0) = root.unwrap_or((V3::zero(body.mass), V3::zero(body.mass)));
    let (f0, n0) = base.wrench_to_base(f0, n0);
    let (f, n) = (force.add(f0), moment.add(n0));
    [f.x, f.y, f.z, n.x, n.y, n.z]
        .into_iter()
        .chain(joints)
        .collect()
}

/// The mass matrix of a floating-base robot, `(6 + n)²`, full and symmetric: base rows and
/// columns first (see the module's doc). Actuator inertia not included.
pub fn floating_crba<S: Scalar>(chain: &Chain<S>, base: &FloatingBase<S>) -> Vec<Vec<S>> {
    let n = chain.joints.len();
    let zero = base.body.mass.zero();
    let mut m = vec![vec![zero; n + 6]; n + 6];
    for (i, row) in crba(chain).into_iter().enumerate() {
        m[i + 6][6..].copy_from_slice(&row);
    }
    let composite = composites(chain);
    let mut whole = base.body;
    for i in 0..n {
        let (mut f, mut nn) = wrench(chain, i, &composite[i]);
        let mut carrier = WrenchCarrier::new(chain);
        let mut child = i;
        while let Some(j) = chain.parent(child) {
            (f, nn) = carrier.to_parent(child, f, nn);
            child = j;
        }
        (f, nn) = carrier.to_parent(child, f, nn);
        let (f, nn) = base.wrench_to_base(f, nn);
        for (k, x) in [f.x, f.y, f.z, nn.x, nn.y, nn.z].into_iter().enumerate() {
            m[k][i + 6] = x;
            m[i + 6][k] = x;
        }
        if chain.parent(i).is_none() {
            let at_frame0 = chain.joints[i].body_to_parent(&composite[i]);
            whole = whole.add(&base.body_to_base(&at_frame0));
        }
    }
    for (k, row) in spatial_inertia(&whole).into_iter().enumerate() {
        m[k][..6].copy_from_slice(&row);
    }
    m
}

/// `[[m 1, −[h]×], [[h]×, I]]` of a body about its origin: the wrench `[f, n]` of a unit
/// `[v̇, ω̇]` at rest.
pub fn spatial_inertia<S: Scalar>(b: &Body<S>) -> [[S; 6]; 6] {
    let (m, h) = (b.mass, b.h);
    let zero = m.zero();
    let [xx, yy, zz, xy, xz, yz] = b.inertia;
    [
        [m, zero, zero, zero, h.z, -h.y],
        [zero, m, zero, -h.z, zero, h.x],
        [zero, zero, m, h.y, -h.x, zero],
        [zero, -h.z, h.y, xx, xy, xz],
        [h.z, zero, -h.x, xy, yy, yz],
        [-h.y, h.x, zero, xz, yz, zz],
    ]
}

/// The generalized gravity `g(q)` of a floating-base robot: [`floating_rnea`] at rest.
pub fn floating_gravity<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    quaternion: [S; 4],
    gravity: V3<S>,
) -> Vec<S> {
    let zeros = vec![gravity.x.zero(); chain.joints.len() + 6];
    floating_rnea(chain, base, quaternion, &zeros, &zeros, gravity)
}
