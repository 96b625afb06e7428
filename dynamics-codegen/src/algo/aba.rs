//! The articulated-body algorithm (Featherstone, *Rigid Body Dynamics Algorithms* §7.3) on a
//! free-flying base: the forward dynamics `a = M⁻¹ (τ − h)` in O(n), without `M`.
//!
//! Spatial vectors are `(linear, angular)` about a joint frame's origin in its axes: a motion
//! `(v, ω)`, a force `(f, n)`; an inertia maps a motion to a force,
//! `I = [[A, B], [Bᵀ, C]]` (a body's `[[m 1, −[h]×], [[h]×, I_O]]`). Gravity is the base's
//! fictitious acceleration: every acceleration below is less `(g, 0)`.
//!
//! 1. Outward, `v_i = X_i v_a + S_i q̇_i`, the velocity-product acceleration
//!    `c_i = v_i ×ₘ S_i q̇_i` and the body's bias force `p_i = v_i ×* I_i v_i`.
//! 2. Inward, the articulated inertia `I^A_i = I_i + Σ_c X_cᵀ I^a_c X_c` and bias
//!    `p^A_i = p_i + Σ_c X_cᵀ p^a_c` over the children c, then `U_i = I^A_i S_i`,
//!    `D_i = S_iᵀ U_i + I_a` (the armature), `u_i = τ_i − S_iᵀ p^A_i`,
//!    `I^a_i = I^A_i − U_i U_iᵀ / D_i` and `p^a_i = p^A_i + I^a_i c_i + U_i u_i / D_i`.
//! 3. The base's articulated inertia `I^A_0` (its own body and the children's, carried to the
//!    base origin) gives its acceleration, `I^A_0 a_0 = τ_0 − p^A_0` (the first six rows of `τ`,
//!    the wrench on the base), solved by the LDLᵀ of the 6 × 6 `I^A_0`; then outward,
//!    `a_i = X_i a_a + c_i`, `q̈_i = (u_i − U_iᵀ a_i) / D_i`, `a_i += S_i q̈_i`.
//!
//! `S_i` is joint i's z axis, angular (revolute) or linear (prismatic): `U_i` is a column of
//! `I^A_i` and `D_i` one of its diagonal entries. Without armature `I^a_i S_i = 0` exactly,
//! which is written as zeros (the trace cannot see it). The pivots `D_i` and those of `I^A_0`
//! are those of `M`'s LDLᵀ from the tips: `M` is positive definite exactly when all are
//! positive.

use super::body::rotate_inertia;
use super::floating::quaternion_rotation;
use super::{Body, Chain, ChainJoint, FloatingBase, JointKind, Ldlt, Mat3, Scalar, V3};
use std::ops::Add;

/// A spatial vector, `(linear, angular)`.
type Spatial<S> = (V3<S>, V3<S>);

/// The forward dynamics by the articulated-body algorithm.
pub struct Articulated<S> {
    /// `a = [v̇, ω̇, q̈_1 …]`, in the velocity's coordinates.
    pub acceleration: Vec<S>,
    /// The joints' `D_i`, then the pivots of the base's articulated inertia.
    pub pivots: Vec<S>,
}

/// A symmetric spatial inertia `[[A, B], [Bᵀ, C]]`, `A` and `C` as `[xx, yy, zz, xy, xz, yz]`.
#[derive(Clone, Copy)]
struct Inertia<S> {
    a: [S; 6],
    b: Mat3<S>,
    c: [S; 6],
}

/// Index of entry `(i, j)` of a symmetric 3 × 3 in `[xx, yy, zz, xy, xz, yz]`.
fn sym(i: usize, j: usize) -> usize {
    match (i.min(j), i.max(j)) {
        (k, l) if k == l => k,
        (0, 1) => 3,
        (0, 2) => 4,
        _ => 5,
    }
}

/// `[p]×`.
fn skew<S: Scalar>(p: V3<S>) -> Mat3<S> {
    let zero = p.x.zero();
    Mat3 {
        m: [[zero, -p.z, p.y], [p.z, zero, -p.x], [-p.y, p.x, zero]],
    }
}

impl<S: Scalar> Inertia<S> {
    /// A rigid body's: `[[m 1, −[h]×], [[h]×, I_O]]`.
    fn of_body(body: &Body<S>) -> Inertia<S> {
        let (m, zero) = (body.mass, body.mass.zero());
        Inertia {
            a: [m, m, m, zero, zero, zero],
            b: skew(body.h).transpose(),
            c: body.inertia,
        }
    }

    /// Entry `(i, j)` of the 6 × 6.
    fn at(&self, i: usize, j: usize) -> S {
        match (i < 3, j < 3) {
            (true, true) => self.a[sym(i, j)],
            (true, false) => self.b.m[i][j - 3],
            (false, true) => self.b.m[j][i - 3],
            (false, false) => self.c[sym(i - 3, j - 3)],
        }
    }

    /// `I x`.
    fn mul(&self, (l, w): Spatial<S>) -> Spatial<S> {
        let x = [l.x, l.y, l.z, w.x, w.y, w.z];
        let row = |i: usize| (0..6).fold(l.x.zero(), |acc, j| acc + self.at(i, j) * x[j]);
        (
            V3::new(row(0), row(1), row(2)),
            V3::new(row(3), row(4), row(5)),
        )
    }

    /// `self + o`.
    fn add(&self, o: &Inertia<S>) -> Inertia<S> {
        let m = |i: usize, j: usize| self.b.m[i][j] + o.b.m[i][j];
        Inertia {
            a: std::array::from_fn(|k| self.a[k] + o.a[k]),
            b: Mat3 {
                m: std::array::from_fn(|i| std::array::from_fn(|j| m(i, j))),
            },
            c: std::array::from_fn(|k| self.c[k] + o.c[k]),
        }
    }

    /// `I − w uᵀ` for `w` parallel to `u` (so symmetric), with row and column `k` exactly
    /// zero where `zero_k` (`I S = U = D w` without armature).
    fn less_outer(&self, w: &[S; 6], u: &[S; 6], k: usize, zero_k: bool) -> Inertia<S> {
        let entry = |i: usize, j: usize| {
            if zero_k && (i == k || j == k) {
                w[0].zero()
            } else {
                self.at(i, j) - w[i] * u[j]
            }
        };
        let pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
        Inertia {
            a: pairs.map(|(i, j)| entry(i, j)),
            b: Mat3 {
                m: std::array::from_fn(|i| std::array::from_fn(|j| entry(i, j + 3))),
            },
            c: pairs.map(|(i, j)| entry(i + 3, j + 3)),
        }
    }

    /// `R I Rᵀ` (blockwise), for `turn_sym` turning a symmetric 3 × 3 and `turn` a vector.
    fn turned(&self, turn_sym: impl Fn([S; 6]) -> [S; 6], turn: impl Fn(V3<S>) -> V3<S>) -> Self {
        let b = &self.b.m;
        let columns = [0, 1, 2].map(|j| turn(V3::new(b[0][j], b[1][j], b[2][j])));
        // Row i of (R B) Rᵀ is R times row i of R B.
        let rows = [0, 1, 2].map(|i| {
            let [x, y, z] = columns.map(|c| [c.x, c.y, c.z][i]);
            turn(V3::new(x, y, z))
        });
        Inertia {
            a: turn_sym(self.a),
            b: Mat3 {
                m: rows.map(|r| [r.x, r.y, r.z]),
            },
            c: turn_sym(self.c),
        }
    }

    /// The same inertia about a point `−p` (a frame whose origin is this one's less `p`, same
    /// axes): `Tᵀ I T` for `T = [[1, −P], [0, 1]]`, `P = [p]×`: `A`,
    /// `B − A P`, `C + P B + (P B)ᵀ − P A P`.
    fn moved_by(&self, p: V3<S>) -> Inertia<S> {
        let skew_p = skew(p);
        let a = Mat3::symmetric(self.a);
        let ap = a.mul(&skew_p);
        let pb = skew_p.mul(&self.b);
        let pap = skew_p.mul(&ap);
        let pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
        Inertia {
            a: self.a,
            b: Mat3 {
                m: std::array::from_fn(|i| std::array::from_fn(|j| self.b.m[i][j] - ap.m[i][j])),
            },
            c: pairs.map(|(i, j)| self.c[sym(i, j)] + (pb.m[i][j] + pb.m[j][i]) - pap.m[i][j]),
        }
    }
}

/// Joint i's inertia carried to its antecedent's frame: `X_iᵀ I X_i`, turned by
/// `Rotz(γ) Rotx(α) Rotz(θ)`, then moved to the antecedent's origin.
fn inertia_to_parent<S: Scalar>(joint: &ChainJoint<S>, i: &Inertia<S>) -> Inertia<S> {
    let turn_sym = |x: [S; 6]| {
        let x = rotate_inertia(x, joint.sin_theta, joint.cos_theta, 0, 1);
        let x = rotate_inertia(x, joint.sin_alpha, joint.cos_alpha, 1, 2);
        match joint.pre {
            Some(p) => rotate_inertia(x, p.sin_gamma, p.cos_gamma, 0, 1),
            None => x,
        }
    };
    i.turned(turn_sym, |v| joint.to_parent(v))
        .moved_by(joint.offset())
}

/// The velocity or acceleration `x` of the antecedent's frame, in joint i's: `X_i x`.
fn motion_to_child<S: Scalar>(joint: &ChainJoint<S>, (l, w): Spatial<S>) -> Spatial<S> {
    (
        joint.to_child(l.add(w.cross(joint.offset()))),
        joint.to_child(w),
    )
}

/// `v ×* (f, n) = (ω × f, ω × n + v × f)`.
fn cross_force<S: Scalar>((v, w): Spatial<S>, (f, n): Spatial<S>) -> Spatial<S> {
    (w.cross(f), w.cross(n).add(v.cross(f)))
}

/// The entry of joint `kind`'s axis in a spatial vector: angular z (revolute), linear z.
fn axis_index(kind: JointKind) -> usize {
    match kind {
        JointKind::Revolute => 5,
        JointKind::Prismatic => 2,
    }
}

/// A spatial vector's six entries.
fn entries<S: Copy>((l, w): Spatial<S>) -> [S; 6] {
    [l.x, l.y, l.z, w.x, w.y, w.z]
}

/// Six entries as a spatial vector.
fn spatial<S: Scalar>(x: [S; 6]) -> Spatial<S> {
    (V3::new(x[0], x[1], x[2]), V3::new(x[3], x[4], x[5]))
}

fn add<S: Scalar>(x: Spatial<S>, y: Spatial<S>) -> Spatial<S> {
    (x.0.add(y.0), x.1.add(y.1))
}

/// What the passes keep of joint i: its velocity-product acceleration `c`, then from the
/// inward pass `U` (a column of `I^A`), `u` and `1 / D`.
struct Kept<S> {
    c: Spatial<S>,
    u_column: [S; 6],
    u: S,
    inverse_pivot: S,
}

/// The first pass: per joint its velocity, its `c` and its body's inertia and bias force.
struct Outward<S> {
    velocity: Vec<Spatial<S>>,
    kept: Vec<Kept<S>>,
    inertia: Vec<Inertia<S>>,
    bias: Vec<Spatial<S>>,
}

/// The base's velocity `(v, ω)` in frame 0's axes at its origin.
fn at_frame0<S: Scalar>(base: &FloatingBase<S>, (l, w): Spatial<S>) -> Spatial<S> {
    let r0 = &base.rotation;
    let l = l.add(w.cross(base.origin));
    (r0.tr_mul_vec(l), r0.tr_mul_vec(w))
}

/// Pass 1: `v_i = X_i v_a + S_i q̇_i`, `c_i = v_i ×ₘ S_i q̇_i`, `p_i = v_i ×* I_i v_i`.
fn outward<S: Scalar>(chain: &Chain<S>, base: &FloatingBase<S>, v: &[S]) -> Outward<S> {
    let n = chain.joints.len();
    let zero = base.body.mass.zero();
    let base_velocity = spatial(std::array::from_fn(|k| v[k]));
    let mut pass = Outward {
        velocity: Vec::with_capacity(n),
        kept: Vec::with_capacity(n),
        inertia: Vec::with_capacity(n),
        bias: Vec::with_capacity(n),
    };
    for (i, joint) in chain.joints.iter().enumerate() {
        let parent = joint
            .parent
            .map_or_else(|| at_frame0(base, base_velocity), |p| pass.velocity[p]);
        let (mut l, mut w) = motion_to_child(joint, parent);
        let qd = v[6 + i];
        let c = match joint.kind {
            JointKind::Revolute => {
                w.z = w.z + qd;
                (l.cross_z(qd), w.cross_z(qd))
            }
            JointKind::Prismatic => {
                l.z = l.z + qd;
                (w.cross_z(qd), V3::zero(zero))
            }
        };
        let body = Inertia::of_body(&joint.body);
        pass.bias.push(cross_force((l, w), body.mul((l, w))));
        pass.inertia.push(body);
        pass.velocity.push((l, w));
        pass.kept.push(Kept {
            c,
            u_column: [zero; 6],
            u: zero,
            inverse_pivot: zero,
        });
    }
    pass
}

/// Pass 2, inward: each joint's `U`, `D`, `u`, its articulated inertia and bias carried to
/// its antecedent, or to the base; returns the base's articulated inertia and bias, and the
/// joints' `D`.
fn inward<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    pass: &mut Outward<S>,
    (tau, armature, base_velocity): (&[S], &[S], Spatial<S>),
) -> (Inertia<S>, Spatial<S>, Vec<S>) {
    let n = chain.joints.len();
    let base_body = Inertia::of_body(&base.body);
    let mut base_inertia = base_body;
    let mut base_bias = cross_force(base_velocity, base_body.mul(base_velocity));
    let mut pivots = Vec::with_capacity(n);
    for i in (0..n).rev() {
        let joint = &chain.joints[i];
        let k = axis_index(joint.kind);
        let column: [S; 6] = std::array::from_fn(|j| pass.inertia[i].at(j, k));
        let d = column[k] + armature[i];
        let r = d.recip();
        let u = tau[6 + i] - entries(pass.bias[i])[k];
        let w = column.map(|x| x * r);
        let articulated = pass.inertia[i].less_outer(&w, &column, k, armature[i].is_zero());
        let ic = articulated.mul(pass.kept[i].c);
        let force = add(add(pass.bias[i], ic), spatial(w.map(|x| x * u)));
        let carried = inertia_to_parent(joint, &articulated);
        let (f, nn) = joint.wrench_to_parent(force.0, force.1);
        match joint.parent {
            Some(p) => {
                pass.inertia[p] = pass.inertia[p].add(&carried);
                pass.bias[p] = add(pass.bias[p], (f, nn));
            }
            None => {
                let r0 = base.rotation;
                let turned =
                    carried.turned(|x| Mat3::symmetric(x).congruence(&r0), |x| r0.mul_vec(x));
                base_inertia = base_inertia.add(&turned.moved_by(base.origin));
                base_bias = add(base_bias, base.wrench_to_base(f, nn));
            }
        }
        pivots.push(d);
        let kept = &mut pass.kept[i];
        (kept.u_column, kept.u, kept.inverse_pivot) = (column, u, r);
    }
    pivots.reverse();
    (base_inertia, base_bias, pivots)
}

/// The forward dynamics of `chain` on the free-flying `base` by the articulated-body
/// algorithm (see the module's doc): the base orientation `quaternion`, velocity `v`
/// (`6 + n`), generalized forces `tau` (`6 + n`, friction already taken off), the joints'
/// `armature`, `gravity` in world axes.
pub fn floating_aba<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    quaternion: [S; 4],
    v: &[S],
    tau: &[S],
    armature: &[S],
    gravity: V3<S>,
) -> Articulated<S> {
    let n = chain.joints.len();
    let zero = base.body.mass.zero();
    let mut pass = outward(chain, base, v);
    let base_velocity = spatial(std::array::from_fn(|k| v[k]));
    let (base_inertia, base_bias, mut pivots) =
        inward(chain, base, &mut pass, (tau, armature, base_velocity));
    // 3. The base's acceleration (less gravity), then the joints', outward.
    let matrix: Vec<Vec<S>> = (0..6)
        .map(|i| (0..6).map(|j| base_inertia.at(i, j)).collect())
        .collect();
    let factors = Ldlt::new(&matrix);
    let rhs: Vec<S> = (0..6).map(|k| tau[k] - entries(base_bias)[k]).collect();
    let solved = factors.solve(&rhs);
    let base_acceleration = spatial(std::array::from_fn(|k| solved[k]));
    let mut acceleration: Vec<Spatial<S>> = Vec::with_capacity(n);
    let mut qdd = Vec::with_capacity(n);
    for (i, joint) in chain.joints.iter().enumerate() {
        let parent = joint
            .parent
            .map_or_else(|| at_frame0(base, base_acceleration), |p| acceleration[p]);
        let kept = &pass.kept[i];
        let a = add(motion_to_child(joint, parent), kept.c);
        let mut x = entries(a);
        let projected = (0..6).fold(zero, |acc, j| acc + kept.u_column[j] * x[j]);
        let qdd_i = (kept.u - projected) * kept.inverse_pivot;
        let k = axis_index(joint.kind);
        x[k] = x[k] + qdd_i;
        acceleration.push(spatial(x));
        qdd.push(qdd_i);
    }
    let g_base = quaternion_rotation(quaternion).tr_mul_vec(gravity);
    let (lin, ang) = base_acceleration;
    let lin = lin.add(g_base);
    let mut out = vec![lin.x, lin.y, lin.z, ang.x, ang.y, ang.z];
    out.extend(qdd);
    pivots.extend(factors.pivots);
    Articulated {
        acceleration: out,
        pivots,
    }
}
