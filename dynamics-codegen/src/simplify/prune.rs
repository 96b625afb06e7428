//! The pruning of one output element within a proven bound.
//!
//! Each `T_i` (`M_ij`, `g_i`) is expanded into its exact canonical polynomial and folded
//! (`C1 C2 − S1 S2` → `C12`, an identity), so `T_i = Σ_k c_k m_k` exactly, each `m_k` a
//! product of symbols. Over an [`Envelope`] (each joint's range `q_j ∈ [lo_j, hi_j]`,
//! `|q̇_j| ≤ v_j`, `|q̈_j| ≤ a_j`) every term is bounded by interval arithmetic,
//! `|c_k m_k| ≤ B_k = |c_k| Π |s|max^e`, where
//!
//! * `|sin(θ_a + θ_b + …)|max`, `|cos(…)|max` are the exact maxima over the interval sum of
//!   the angles' ranges (each shifted by its joint's constant offset);
//! * `|q̇_j|max = v_j`, `|q̈_j|max = a_j`, a prismatic `|q_j|max = max(|lo_j|, |hi_j|)`, and
//!   `|sgn|`, `|tanh|` ≤ 1;
//! * a parameter of the robot (a struct field) has no bound: the robot is refused.
//!
//! The terms with the smallest bounds are dropped while the sum of the dropped bounds stays
//! within the joint's tolerance `T_i`; the rest are kept. By the triangle inequality, at every
//! state of the envelope
//!
//! ```text
//! |T_i − T_i,simplified| = |Σ_dropped c_k m_k| ≤ Σ_dropped B_k ≤ T_i,
//! ```
//!
//! and `Σ_dropped B_k` is the proven bound printed. Each `B_k` is raised by a relative 1e-12
//! and the sine and cosine maxima rounded outward, for the floating point of the bound itself.

use super::bound;
use crate::model::Envelope;
use crate::poly::Monomial;
use crate::symbolic::Number;
use std::collections::BTreeMap;

/// A dropped term and the bound of its absolute value over the envelope.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounded {
    /// The term's product of symbols.
    pub monomial: Monomial,
    /// Its coefficient.
    pub coef: Number,
    /// The largest `|coef · monomial|` over the envelope (an upper bound).
    pub bound: f64,
}

/// One joint torque's pruning.
#[derive(Clone, Debug)]
pub struct Pruning {
    /// The whole polynomial, folded.
    pub full: BTreeMap<Monomial, Number>,
    /// The terms kept.
    pub kept: BTreeMap<Monomial, Number>,
    /// The terms dropped, largest bound first.
    pub dropped: Vec<Bounded>,
    /// The proven bound of `|full − kept|` over the envelope: the dropped terms' bounds summed.
    pub bound: f64,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// A bound of `|full|` over the envelope: every term's bound summed.
    pub magnitude: f64,
}

/// Drops the terms of `full` with the smallest bounds over `envelope` while their summed
/// bound stays within `tolerance`.
///
/// # Errors
/// A term holding a parameter of the robot, which no envelope bounds.
pub fn prune(
    full: BTreeMap<Monomial, Number>,
    envelope: &Envelope,
    offsets: &[f64],
    tolerance: f64,
) -> Result<Pruning, String> {
    let mut bounded = full
        .iter()
        .map(|(m, c)| {
            Ok(Bounded {
                monomial: m.clone(),
                coef: *c,
                bound: bound::term_bound(m, *c, envelope, offsets)?,
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    // Smallest first; ties in the canonical order, so that the choice is reproducible.
    bounded.sort_by(|a, b| {
        a.bound
            .total_cmp(&b.bound)
            .then_with(|| a.monomial.cmp(&b.monomial))
    });
    let magnitude = bounded.iter().map(|b| b.bound).sum();
    let mut bound = 0.0;
    let mut cut = 0;
    while cut < bounded.len() && bound + bounded[cut].bound <= tolerance {
        bound += bounded[cut].bound;
        cut += 1;
    }
    let kept = bounded[cut..]
        .iter()
        .map(|b| (b.monomial.clone(), b.coef))
        .collect();
    let mut dropped = bounded;
    dropped.truncate(cut);
    dropped.reverse();
    Ok(Pruning {
        full,
        kept,
        dropped,
        bound,
        tolerance,
        magnitude,
    })
}

/// The mass matrix element `M_ij`'s tolerance for joint tolerances `t` over `envelope`:
/// `min(t_i, t_j) / Σ_k a_k`, so that the pruned `M q̈` is within `t_i` too (0, nothing
/// dropped, where no joint accelerates).
#[must_use]
pub fn mass_tolerance(t: &[f64], envelope: &Envelope, i: usize, j: usize) -> f64 {
    let accelerations: f64 = envelope.joints.iter().map(|j| j.acceleration).sum();
    if accelerations > 0.0 {
        t[i].min(t[j]) / accelerations
    } else {
        0.0
    }
}
