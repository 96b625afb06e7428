//! The Coriolis matrix in O(n²) carries, after Echeandia and Wensing (2021), without the
//! derivatives of `M`.
//!
//! With `p = M q̇` (the generalized momentum), `C = ½(Ṁ + P)`, `P_ij = ∂p_i/∂q_j − ∂p_j/∂q_i`
//! (q̇ held): the Christoffel form, `Ṁ = C + Cᵀ`. In spatial vectors (motion `(ω, v)`, force
//! `(n, f)`, each in its joint frame), with `S_j` joint j's axis, `Ic_j` the composite body of
//! link j and its descendants (links j..n in a chain), `hc_j = Σ_k I_k v_k` over them its
//! momentum and `İc_j` its rate; every carry goes from a joint to its antecedent:
//!
//! * `a_j = Ic_j Ṡ_j + ½(İc_j S_j + S_j ×* hc_j)`, `b_j = ½(İc_j S_j − S_j ×* hc_j)`,
//!   `Ṡ_j = v_j × S_j`;
//! * for i = j and each ancestor i of j, with `a_j`, `b_j` and `Ic_j S_j` carried to J_i:
//!   `C_ij = S_i · a_j` and `C_ji = Ṡ_i · Ic_j S_j + S_i · b_j`; elsewhere (neither an
//!   ancestor of the other) `C_ij = 0`.
//!
//! `İc_j` in J_j's axes is `v_j ×* Ic_j − Ic_j v_j × + L_j`, where `L_j` is the rate of `Ic_j`
//! as J_j sees it: each joint k below j turning at `q̇_k` adds its commutator, carried inward as in
//! [`super::crba_derivative`] (a prismatic joint adds the rate of a shift along z instead).
//! `None` for a chain that turns through sums of angles.

use super::crba::{composites, turn_derivative, wrench};
use super::{Body, Chain, ChainJoint, JointKind, Scalar, V3};
use std::ops::Add;

/// A force `(f, n)`: force and moment about the frame's origin.
type Force<S> = (V3<S>, V3<S>);

/// `I (ω, v)` for a body about the frame's origin: `(m v − h × ω, I ω + h × v)`.
fn momentum<S: Scalar>(b: &Body<S>, omega: V3<S>, v: V3<S>) -> Force<S> {
    (
        v.scale(b.mass).add(omega.cross(b.h)),
        b.inertia_mul(omega).add(b.h.cross(v)),
    )
}

/// `(ω, v) ×* (f, n) = (ω × f, ω × n + v × f)`.
fn cross_force<S: Scalar>(omega: V3<S>, v: V3<S>, (f, n): Force<S>) -> Force<S> {
    (omega.cross(f), omega.cross(n).add(v.cross(f)))
}

/// `z × u`.
fn z_cross<S: Scalar>(u: V3<S>) -> V3<S> {
    V3::new(-u.y, u.x, u.x.zero())
}

fn add<S: Scalar>((f, n): Force<S>, (g, m): Force<S>) -> Force<S> {
    (f.add(g), n.add(m))
}

fn sub<S: Scalar>((f, n): Force<S>, (g, m): Force<S>) -> Force<S> {
    (f.add(-g), n.add(-m))
}

fn half<S: Scalar>((f, n): Force<S>) -> Force<S> {
    let h = f.x.constant(crate::symbolic::Number::Rational(1, 2));
    (f.scale(h), n.scale(h))
}

fn scaled_body<S: Scalar>(b: &Body<S>, k: S) -> Body<S> {
    Body {
        mass: b.mass * k,
        h: b.h.scale(k),
        inertia: b.inertia.map(|x| x * k),
    }
}

/// What the columns of `C` are built from, per link i: its twist `(ω_i, v_i)` in J_i (`v_i`
/// the velocity of J_i's origin), the composite `Ic_i`, its momentum `hc_i` and its rate `L_i`
/// as J_i sees it (`None` for the last link, whose composite is one rigid link).
struct Composites<S> {
    /// Zero, in the scalar's context.
    zero: S,
    omega: Vec<V3<S>>,
    vel: Vec<V3<S>>,
    body: Vec<Body<S>>,
    momentum: Vec<Force<S>>,
    rate: Vec<Option<Body<S>>>,
}

/// The Coriolis matrix of `chain` at rates `qd`; `None` if the chain sums angles.
pub fn coriolis_matrix<S: Scalar>(chain: &Chain<S>, qd: &[S]) -> Option<Vec<Vec<S>>> {
    let n = chain.joints.len();
    if chain.joints.iter().any(|j| j.sum_angles) {
        return None;
    }
    let zero = chain.joints.first()?.a.zero();
    let (omega, vel) = link_twists(chain, qd, zero);
    let body = composites(chain);
    let momentum = composite_momenta(chain, &omega, &vel);
    let rate = composite_rates(chain, &body, qd);
    let composites = Composites {
        zero,
        omega,
        vel,
        body,
        momentum,
        rate,
    };
    let mut c = vec![vec![zero; n]; n];
    for j in 0..n {
        fill_column(chain, &composites, j, &mut c);
    }
    Some(c)
}

/// Link twists `(ω_i, v_i)` in J_i, `v_i` the velocity of J_i's origin.
fn link_twists<S: Scalar>(chain: &Chain<S>, qd: &[S], zero: S) -> (Vec<V3<S>>, Vec<V3<S>>) {
    let n = chain.joints.len();
    let mut omega = Vec::with_capacity(n);
    let mut vel = Vec::with_capacity(n);
    for (i, joint) in chain.joints.iter().enumerate() {
        let (w, v) = match joint.parent {
            Some(p) => {
                let (w, v): (V3<S>, V3<S>) = (omega[p], vel[p]);
                (
                    joint.to_child(w),
                    joint.to_child(v.add(w.cross(joint.offset()))),
                )
            }
            None => (V3::zero(zero), V3::zero(zero)),
        };
        let rate = V3::new(zero, zero, qd[i]);
        match joint.kind {
            JointKind::Revolute => {
                omega.push(w.add(rate));
                vel.push(v);
            }
            JointKind::Prismatic => {
                omega.push(w);
                vel.push(v.add(rate));
            }
        }
    }
    (omega, vel)
}

/// Momenta of the composites, `hc_i = I_i v_i + Σ_{a(c) = i} X_c(hc_c)`.
fn composite_momenta<S: Scalar>(chain: &Chain<S>, omega: &[V3<S>], vel: &[V3<S>]) -> Vec<Force<S>> {
    let n = chain.joints.len();
    let mut hc: Vec<Force<S>> = (0..n)
        .map(|i| momentum(&chain.joints[i].body, omega[i], vel[i]))
        .collect();
    for c in (1..n).rev() {
        if let Some(i) = chain.parent(c) {
            let (f, nn) = hc[c];
            hc[i] = add(hc[i], chain.joints[c].wrench_to_parent(f, nn));
        }
    }
    hc
}

/// Rates of the composites as their frames see them: each joint beyond adds its own,
/// carried inward.
fn composite_rates<S: Scalar>(
    chain: &Chain<S>,
    composite: &[Body<S>],
    qd: &[S],
) -> Vec<Option<Body<S>>> {
    let n = chain.joints.len();
    let mut rate: Vec<Option<Body<S>>> = vec![None; n];
    for c in (1..n).rev() {
        let Some(i) = chain.parent(c) else {
            continue;
        };
        let joint = &chain.joints[c];
        let carried = rate[c].as_ref().map(|r| joint.body_to_parent(r));
        let own = match joint.kind {
            JointKind::Revolute => commutator(joint, &composite[c], qd[c]),
            JointKind::Prismatic => slide(joint, &composite[c], qd[c]),
        };
        let through = match carried {
            Some(c) => c.add(&own),
            None => own,
        };
        rate[i] = Some(match rate[i] {
            Some(sibling) => sibling.add(&through),
            None => through,
        });
    }
    rate
}

/// `C_jj`, and `C_ij`, `C_ji` for `i < j`: `a_j`, `b_j` and `Ic_j S_j` carried inward.
fn fill_column<S: Scalar>(chain: &Chain<S>, at: &Composites<S>, j: usize, c: &mut [Vec<S>]) {
    let zero = at.zero;
    let f2 = wrench(chain, j, &at.body[j]);
    let (w, v) = (at.omega[j], at.vel[j]);
    // Ṡ_j = (ω_j × z, v_j × z) = −(z × ω_j, z × v_j), or (0, ω_j × z) when prismatic.
    let revolute = chain.joints[j].kind == JointKind::Revolute;
    let ic_s_dot = if revolute {
        momentum(&at.body[j], -z_cross(w), -z_cross(v))
    } else {
        momentum(&at.body[j], V3::zero(zero), -z_cross(w))
    };
    let l_s = at.rate[j]
        .as_ref()
        .map_or((V3::zero(zero), V3::zero(zero)), |r| wrench(chain, j, r));
    let hc = at.momentum[j];
    let s_hc = if revolute {
        (z_cross(hc.0), z_cross(hc.1))
    } else {
        (V3::zero(zero), z_cross(hc.0))
    };
    // İc S = v ×* f2 − Ic Ṡ + L S.
    let ic_rate_s = add(sub(cross_force(w, v, f2), ic_s_dot), l_s);
    let mut a = add(ic_s_dot, half(add(ic_rate_s, s_hc)));
    let mut b = half(sub(ic_rate_s, s_hc));
    let mut f2 = f2;
    c[j][j] = axis(chain, j, a);
    let mut child = j;
    while let Some(i) = chain.parent(child) {
        let through = &chain.joints[child];
        child = i;
        f2 = through.wrench_to_parent(f2.0, f2.1);
        let (wi, vi) = (at.omega[i], at.vel[i]);
        // Ṡ_i · Ic_j S_j with Ṡ_i = (ω_i × z, v_i × z), or (0, ω_i × z).
        let s_dot_f2 = match chain.joints[i].kind {
            JointKind::Revolute => wi.y * f2.1.x - wi.x * f2.1.y + (vi.y * f2.0.x - vi.x * f2.0.y),
            JointKind::Prismatic => wi.y * f2.0.x - wi.x * f2.0.y,
        };
        a = through.wrench_to_parent(a.0, a.1);
        b = through.wrench_to_parent(b.0, b.1);
        c[i][j] = axis(chain, i, a);
        c[j][i] = s_dot_f2 + axis(chain, i, b);
    }
}

/// `S_i ·` a force: its moment's or its force's z component.
fn axis<S: Scalar>(chain: &Chain<S>, i: usize, (f, n): Force<S>) -> S {
    match chain.joints[i].kind {
        JointKind::Revolute => n.z,
        JointKind::Prismatic => f.z,
    }
}

/// `q̇ ∂/∂d` of `X(d) Ic` through prismatic `joint`, which shifts `Ic` by `d` along z before
/// the rest of its transform: the rate of a shift, `(0, m z, 2(z·h) 1 − z hᵀ − h zᵀ)`, of
/// the shifted body, carried through the joint at d = 0.
fn slide<S: Scalar>(joint: &ChainJoint<S>, ic: &Body<S>, qd: S) -> Body<S> {
    let zero = qd.zero();
    let shifted = ic.moved_by(V3::new(zero, zero, joint.d));
    let h = shifted.h;
    let hz2 = h.z + h.z;
    let rate = Body {
        mass: zero,
        h: V3::new(zero, zero, shifted.mass),
        inertia: [hz2, hz2, zero, zero, -h.x, -h.y],
    };
    let frozen = ChainJoint { d: zero, ..*joint };
    scaled_body(&frozen.body_to_parent(&rate), qd)
}

/// `q̇ ∂/∂θ` of `X(θ) Ic` through revolute `joint` ([`turn_derivative`]).
fn commutator<S: Scalar>(joint: &ChainJoint<S>, ic: &Body<S>, qd: S) -> Body<S> {
    scaled_body(&turn_derivative(joint, ic), qd)
}
