//! The rigid bodies of the chain: a moving joint's child link with every link fixed to it,
//! combined exactly into one mass, centre of mass and inertia tensor.
//!
//! Part k, with mass `m_k`, centre of mass `c_k` and inertia `I_k` (about `c_k`) in its own
//! axes, sits at pose `(R_k, t_k)` in the body frame. In body axes its centre of mass is
//! `R_k c_k + t_k` and its inertia `R_k I_k R_kᵀ` (the inertial `<origin rpy>` first turns
//! `I_k` to the link's axes). The body has `m = Σ m_k`, `c = Σ m_k c_k / m`, and, by the
//! parallel-axis theorem, `I = Σ I_k + m_k (|d_k|² 1 − d_k d_kᵀ)` with `d_k = c_k − c`.

use super::xml::Inertial;
use crate::model::{rotate_inertia, Pose, Value};

/// Mass, centre of mass and inertia tensor `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` about it.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Body {
    pub mass: Value,
    pub com: [Value; 3],
    pub inertia: [Value; 6],
}

impl Body {
    /// A link's `<inertial>` (none: a massless point) at `pose` in the body frame.
    pub fn part(inertial: Option<&Inertial>, pose: &Pose) -> Body {
        let Some(inertial) = inertial else {
            return Body {
                mass: Value::zero(),
                com: Default::default(),
                inertia: Default::default(),
            };
        };
        // The quarter turns of `rpy` are exact, and no angle names a field: `pose()` succeeds.
        let axes = inertial.origin.pose().unwrap_or_default();
        let rotation = pose.then(&axes).rotation;
        Body {
            mass: inertial.mass.clone(),
            com: pose.apply(&inertial.origin.xyz),
            inertia: rotate_inertia(&rotation, &inertial.inertia),
        }
    }

    /// The parts as one rigid body; a massless body has its centre of mass at the origin.
    pub fn combine(parts: &[Body]) -> Body {
        if let [one] = parts {
            return one.clone();
        }
        let mass = sum(parts.iter().map(|p| p.mass.clone()));
        let per_mass = mass.exact().and_then(crate::symbolic::Number::recip);
        let com: [Value; 3] = std::array::from_fn(|i| match per_mass {
            Some(per_mass) => {
                sum(parts.iter().map(|p| p.mass.clone() * p.com[i].clone())) * Value::num(per_mass)
            }
            None => Value::zero(),
        });
        let inertia = std::array::from_fn(|e| {
            sum(parts.iter().map(|p| {
                let d: [Value; 3] = std::array::from_fn(|i| p.com[i].clone() - com[i].clone());
                p.inertia[e].clone() + p.mass.clone() * shift(&d, e)
            }))
        });
        Body { mass, com, inertia }
    }
}

/// Entry `e` of `|d|² 1 − d dᵀ`, in the order `[xx, yy, zz, xy, xz, yz]`.
fn shift(d: &[Value; 3], e: usize) -> Value {
    let sq = |i: usize| d[i].clone() * d[i].clone();
    match e {
        0 => sq(1) + sq(2),
        1 => sq(0) + sq(2),
        2 => sq(0) + sq(1),
        3 => -(d[0].clone() * d[1].clone()),
        4 => -(d[0].clone() * d[2].clone()),
        _ => -(d[1].clone() * d[2].clone()),
    }
}

fn sum(values: impl Iterator<Item = Value>) -> Value {
    values.fold(Value::zero(), |acc, v| acc + v)
}
