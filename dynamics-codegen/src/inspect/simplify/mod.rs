//! Simplified joint torques, mass matrix and gravity torques with a proven error bound (issue
//! 30); the derive's `simplify(...)` prunes with the same functions.
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

mod bound;
pub mod eval;
mod report;
#[cfg(test)]
mod tests;

pub use bound::{max_abs_cos, max_abs_sin};

use super::expand::Expander;
use super::label::{Label, Quantity};
use super::sections::{Entry, Section};
use super::{arrange::arrange, Inspection, Limits, Monomial};
use crate::model::Robot;
pub use crate::model::{Envelope, JointEnvelope};
use crate::symbolic::Number;
use crate::trace::Equations;
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

/// The joint torques, mass matrix and gravity torques of a robot pruned within their
/// tolerances, ready to print.
pub struct Simplified {
    inspection: Inspection,
    envelope: Envelope,
    /// The joint torques', one per joint.
    pub prunings: Vec<Pruning>,
    /// The mass matrix's upper triangle (`D11`, `D12`, …) and the gravity torques' (`D1`, …),
    /// by name.
    pub others: Vec<(String, Pruning)>,
    /// The robot's constants behind its symbols, as [`eval::constants`] gives them.
    pub constants: eval::Constants,
}

/// Expands each joint torque, mass matrix element and gravity torque of `eq`, folds it and
/// prunes it over `envelope` within `tolerance` (one per joint; [`mass_tolerance`] for M):
/// see the module's documentation for the bound.
///
/// # Errors
/// An envelope or tolerance list whose length is not the joints', or a robot with a parameter
/// (a struct field) in its outputs or angle offsets.
pub fn inspect_simplified(
    eq: &Equations,
    robot: &Robot,
    envelope: &Envelope,
    tolerance: &[f64],
) -> Result<Simplified, String> {
    let n = eq.dof;
    if envelope.joints.len() != n || tolerance.len() != n {
        return Err(format!(
            "the envelope and the tolerances need one value per joint ({n})"
        ));
    }
    let constants = eval::constants(eq)?;
    let mut expander = Expander::new(eq, Limits::UNBOUNDED);
    let mut one = |id, name: &str, t: f64| {
        let full = expander
            .folded(id)
            .ok_or_else(|| format!("{name} is not a polynomial in the joint variables"))?;
        prune(full, envelope, &constants.offsets, t).map_err(|e| format!("{name}: {e}"))
    };
    let mut sections = Vec::new();
    let mut prunings = Vec::with_capacity(n);
    let mut others = Vec::new();
    let mut entries = Vec::new();
    for (i, &id) in eq.tau.iter().enumerate() {
        let pruning = one(id, &format!("T{}", i + 1), tolerance[i])?;
        entries.push(entry(Label::new(Quantity::Torque, &[i]), &pruning));
        prunings.push(pruning);
    }
    sections.push(section(Quantity::Torque, &mut entries));
    for i in 0..n {
        for j in i..n {
            let name = format!("D{}{}", i + 1, j + 1);
            let pruning = one(
                eq.mass[i][j],
                &name,
                mass_tolerance(tolerance, envelope, i, j),
            )?;
            entries.push(entry(Label::new(Quantity::Inertia, &[i, j]), &pruning));
            others.push((name, pruning));
        }
    }
    sections.push(section(Quantity::Inertia, &mut entries));
    for (quantity, letter, ids) in [
        (Quantity::CoriolisTorque, "C", &eq.coriolis_torques),
        (Quantity::Gravity, "D", &eq.gravity),
    ] {
        for (i, &id) in ids.iter().enumerate() {
            let name = format!("{letter}{}", i + 1);
            let pruning = one(id, &name, tolerance[i])?;
            entries.push(entry(Label::new(quantity, &[i]), &pruning));
            others.push((name, pruning));
        }
        sections.push(section(quantity, &mut entries));
    }
    Ok(Simplified {
        inspection: Inspection::new(eq, robot, false, sections, Limits::UNBOUNDED),
        envelope: envelope.clone(),
        prunings,
        others,
        constants,
    })
}

/// The printed entry of a pruned element: what it keeps.
fn entry(label: Label, pruning: &Pruning) -> Entry {
    Entry {
        labels: vec![label],
        value: Some(arrange(pruning.kept.clone().into_iter().collect())),
    }
}

/// The section of `quantity` holding `entries` (taken).
fn section(quantity: Quantity, entries: &mut Vec<Entry>) -> Section {
    Section {
        quantity,
        entries: std::mem::take(entries),
    }
}
