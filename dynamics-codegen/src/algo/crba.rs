//! Composite rigid body algorithm: the mass matrix `M(q)`, the book's D_ij (eq. 6.43)
//! without actuator inertia.
//!
//! The composite body of link i and its descendants (links i..n in a chain),
//! `Ic_i = body_i + Σ_{a(c) = i} X_c(Ic_c)` over the joints c whose antecedent is i, moved by a
//! unit acceleration of joint i alone exerts the wrench `(f, n) = (z × h, I z)` (revolute) or
//! `(m z, h × z)` (prismatic) at J_i. `M_ii` is its component on joint i's axis; carried to
//! each ancestor j in turn, antecedent by antecedent (`f ← R f`, `n ← R n + p × R f`), its
//! component on joint j's axis is `M_ji`. Where neither of i, j is an ancestor of the other
//! nothing moves both: `M_ij` is an exact zero. Column j of
//! the result equals [`super::rnea`] with `qd = 0`, `qdd = e_j` and no gravity. The wrenches
//! go through a [`super::WrenchCarrier`], which turns moments through runs of parallel joints
//! in one step where the chain asks for it.

use super::{Body, Chain, ChainJoint, JointKind, Scalar, WrenchCarrier, V3};
use std::ops::Add;

/// The joint-space mass matrix of `chain`, full and symmetric.
pub fn crba<S: Scalar>(chain: &Chain<S>) -> Vec<Vec<S>> {
    let n = chain.joints.len();
    let Some(first) = chain.joints.first() else {
        return Vec::new();
    };
    let zero = first.a.zero();
    let mut m = vec![vec![zero; n]; n];
    let composite = composites(chain);
    for i in 0..n {
        let (mut f, mut nn) = wrench(chain, i, &composite[i]);
        m[i][i] = axis(chain, i, f, nn);
        let mut carrier = WrenchCarrier::new(chain);
        let mut child = i;
        while let Some(j) = chain.parent(child) {
            (f, nn) = carrier.to_parent(child, f, nn);
            m[j][i] = axis(chain, j, f, nn);
            m[i][j] = m[j][i];
            child = j;
        }
    }
    m
}

/// `∂M/∂q_k` for a revolute joint k, differentiating the algorithm rather than its trace:
/// turning by θ_k moves what lies beyond joint k, and the derivative of anything turned is the
/// axis crossed with it, `∂(R v)/∂θ = z × R v` and `∂(R I Rᵀ)/∂θ = [z]× I' − I' [z]×` for the
/// turned `I' = R I Rᵀ`: components of values already computed, swapped and negated, where
/// differentiating the trace would multiply by sines and cosines again. So `∂Ic_i` (i < k) is
/// that commutator for `Ic_k` carried down like a body without mass, and a wrench carried
/// through joint k adds the carried `(z × f, z × n)` to its derivative. `None` for a prismatic
/// joint.
pub fn crba_derivative<S: Scalar>(chain: &Chain<S>, k: usize) -> Option<Vec<Vec<S>>> {
    let n = chain.joints.len();
    let joint = chain.joints.get(k)?;
    if joint.kind != JointKind::Revolute {
        return None;
    }
    let zero = joint.a.zero();
    let composite = composites(chain);
    // ∂Ic_i for i < k.
    // ∂Ic_i for the ancestors i of k.
    let mut d_composite: Vec<Option<Body<S>>> = vec![None; n];
    if let Some(p) = joint.parent {
        d_composite[p] = Some(turn_derivative(joint, &composite[k]));
        let mut child = p;
        while let Some(i) = chain.parent(child) {
            d_composite[i] = d_composite[child]
                .as_ref()
                .map(|d| chain.joints[child].body_to_parent(d));
            child = i;
        }
    }
    let mut dm = vec![vec![zero; n]; n];
    for i in 0..n {
        let (mut f, mut nn) = wrench(chain, i, &composite[i]);
        let mut d = d_composite[i].as_ref().map(|b| wrench(chain, i, b));
        if let Some((df, dn)) = d {
            dm[i][i] = axis(chain, i, df, dn);
        }
        let mut child = i;
        while let Some(j) = chain.parent(child) {
            let through = &chain.joints[child];
            // ∂(R v) = z × (Rotz v) carried on by the twist: Rotz v is already computed.
            let turned = (child == k).then(|| {
                let cross_z = |v: V3<S>| {
                    let u = through.to_turned(v);
                    V3::new(-u.y, u.x, zero)
                };
                through.wrench_from_turned(cross_z(f), cross_z(nn))
            });
            d = d.map(|(df, dn)| transport(through, df, dn));
            d = match (d, turned) {
                (Some((a, b)), Some((c, e))) => Some((a.add(c), b.add(e))),
                (x, None) | (None, x) => x,
            };
            (f, nn) = transport(through, f, nn);
            if let Some((df, dn)) = d {
                dm[j][i] = axis(chain, j, df, dn);
                dm[i][j] = dm[j][i];
            }
            child = j;
        }
    }
    Some(dm)
}

/// `∂/∂θ` of `X(θ) b` for revolute `joint`, `b` given in the joint's frame: the commutator
/// `[z]× I' − I' [z]×` (and `z × h'`) of `b` turned by θ, carried through the joint frozen at
/// θ = 0, since the rest of the carry (twist and offset) is linear.
pub(super) fn turn_derivative<S: Scalar>(joint: &ChainJoint<S>, b: &Body<S>) -> Body<S> {
    let zero = b.mass.zero();
    let h = joint.to_turned(b.h);
    let [xx, yy, _, xy, xz, yz] = joint.turned_inertia(b.inertia);
    let d_turned = Body {
        mass: zero,
        h: V3::new(-h.y, h.x, zero),
        inertia: [-(xy + xy), xy + xy, zero, xx - yy, -yz, xz],
    };
    let frozen = ChainJoint {
        sin_theta: zero,
        cos_theta: zero.one(),
        ..*joint
    };
    frozen.body_to_parent(&d_turned)
}

/// The composite bodies `Ic_i = body_i + Σ_{c: a(c) = i} X_c(Ic_c)`, each about J_i: link i
/// and all its descendants.
pub(super) fn composites<S: Scalar>(chain: &Chain<S>) -> Vec<Body<S>> {
    let n = chain.joints.len();
    let mut composite: Vec<Body<S>> = chain.joints.iter().map(|j| j.body).collect();
    for c in (1..n).rev() {
        if let Some(i) = chain.parent(c) {
            let moved = chain.joints[c].body_to_parent(&composite[c]);
            composite[i] = composite[i].add(&moved);
        }
    }
    composite
}

/// The wrench at J_i of `body` given a unit acceleration of joint i.
pub(super) fn wrench<S: Scalar>(chain: &Chain<S>, i: usize, body: &Body<S>) -> (V3<S>, V3<S>) {
    let zero = body.mass.zero();
    let z = V3::new(zero, zero, zero.one());
    match chain.joints[i].kind {
        JointKind::Revolute => (z.cross(body.h), body.inertia_mul(z)),
        JointKind::Prismatic => (z.scale(body.mass), body.h.cross(z)),
    }
}

/// A wrench at J_i carried to J_{i−1}: `f ← R f`, `n ← R n + p × R f`.
fn transport<S: Scalar>(child: &ChainJoint<S>, f: V3<S>, nn: V3<S>) -> (V3<S>, V3<S>) {
    child.wrench_to_parent(f, nn)
}

/// The component of a wrench on joint k's axis.
fn axis<S: Scalar>(chain: &Chain<S>, k: usize, f: V3<S>, nn: V3<S>) -> S {
    match chain.joints[k].kind {
        JointKind::Revolute => nn.z,
        JointKind::Prismatic => f.z,
    }
}
