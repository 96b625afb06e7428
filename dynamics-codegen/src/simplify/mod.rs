//! The simplified models' stage (opt-in, `simplify(...)`): after the trace, each joint torque,
//! mass matrix element and gravity torque is expanded into its exact folded polynomial, the
//! terms whose summed interval bound over the envelope stays within the element's tolerance
//! are dropped ([`crate::inspect::simplify::prune`], the bound of `dynamics inspect
//! --simplified`), and what is kept is factored back into the graph (`horner`), where the
//! emission finds it as the outputs of the family `Simplified`.
//!
//! Tolerances: `τ_i` and `g_i` within the joint's `t_i`; `M_ij` within
//! `min(t_i, t_j) / Σ_k a_k` (`a` the envelope's accelerations), so that the torque error of
//! the pruned `M q̈` stays within `t_i` too.

mod horner;
#[cfg(test)]
mod tests;

use crate::inspect::simplify::{eval, mass_tolerance, prune, Pruning};
use crate::inspect::{Expander, Limits};
use crate::method::Family;
use crate::model::Simplification;
use crate::symbolic::NodeId;
use crate::trace::{Equations, PrunedElement, SimplifiedEquations};
use horner::Builder;

/// Most terms a pruned output (all its elements) may keep. Past it the expanded form costs
/// several times the exact recursive one, and one function of thousands of `let`s overflows
/// the stack of rustc's debug-info pass (a 6-joint random arm's τ keeping 3867 terms did).
const MAX_KEPT: usize = 1500;

/// The pruning of one output element.
struct Pruned {
    pruning: Pruning,
}

impl Pruned {
    fn element(&self) -> PrunedElement {
        PrunedElement {
            bound: self.pruning.bound,
            tolerance: self.pruning.tolerance,
            terms: self.pruning.full.len(),
            kept: self.pruning.kept.len(),
        }
    }
}

/// Builds the pruned τ, M and g of `eq` for `request` into its graph and adds the family
/// `Simplified` to its families.
///
/// # Errors
/// A request whose lists are not one value per joint, an output that is not a polynomial in
/// the joint variables, or a parameter of the robot (a struct field) in an output or an angle
/// offset: no envelope bounds it.
pub fn add(eq: &mut Equations, request: &Simplification) -> Result<(), String> {
    let n = eq.dof;
    if request.tolerance.len() != n || request.envelope.joints.len() != n {
        return Err(format!(
            "the envelope and the tolerances need one value per joint ({n})"
        ));
    }
    let constants = eval::constants(eq)?;
    let (tau, mass, gravity) = {
        let mut p = Pruner {
            expander: Expander::new(eq, Limits::UNBOUNDED),
            request,
            offsets: &constants.offsets,
        };
        let t = &request.tolerance;
        let tau = p.vector(&eq.tau, "T", t)?;
        let gravity = p.vector(&eq.gravity, "D", t)?;
        let mass = p.mass(&eq.mass, t)?;
        (tau, mass, gravity)
    };
    let kept = |p: &[Pruned]| p.iter().map(|p| p.pruning.kept.len()).sum::<usize>();
    for (name, count) in [
        ("τ", kept(&tau)),
        ("g", kept(&gravity)),
        ("M", mass.iter().map(|r| kept(r)).sum()),
    ] {
        if count > MAX_KEPT {
            return Err(format!(
                "the pruned {name} keeps {count} terms, more than {MAX_KEPT}: expanded, this \
                 robot's equations are larger than its exact recursive form by far; raise the \
                 tolerance or narrow the envelope"
            ));
        }
    }
    let mut builder = Builder::new(&mut eq.graph);
    let mut build = |p: &Pruned| builder.build(&p.pruning.kept);
    let tau_ids = tau.iter().map(&mut build).collect::<Result<_, _>>()?;
    let gravity_ids = gravity.iter().map(&mut build).collect::<Result<_, _>>()?;
    let mut mass_ids = vec![vec![NodeId(0); n]; n];
    for (i, row) in mass.iter().enumerate() {
        for (k, p) in row.iter().enumerate() {
            let id = build(p)?;
            mass_ids[i][i + k] = id;
            mass_ids[i + k][i] = id;
        }
    }
    let mass_bounds = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| mass[i.min(j)][i.abs_diff(j)].element())
                .collect()
        })
        .collect();
    eq.simplified = Some(SimplifiedEquations {
        request: request.clone(),
        tau: tau_ids,
        mass: mass_ids,
        gravity: gravity_ids,
        tau_bounds: tau.iter().map(Pruned::element).collect(),
        mass_bounds,
        gravity_bounds: gravity.iter().map(Pruned::element).collect(),
    });
    eq.families = eq.families.with(Family::Simplified);
    Ok(())
}

/// Expands and prunes output elements over one request.
struct Pruner<'a> {
    expander: Expander<'a>,
    request: &'a Simplification,
    offsets: &'a [f64],
}

impl Pruner<'_> {
    /// Element `id`, named `name` in errors, pruned within `tolerance`.
    fn one(&mut self, id: NodeId, name: &str, tolerance: f64) -> Result<Pruned, String> {
        let full = self
            .expander
            .folded(id)
            .ok_or_else(|| format!("{name} is not a polynomial in the joint variables"))?;
        let pruning = prune(full, &self.request.envelope, self.offsets, tolerance)
            .map_err(|e| format!("{name}: {e}"))?;
        Ok(Pruned { pruning })
    }

    /// A vector of elements, `T1`, `T2`, …, each within its joint's tolerance.
    fn vector(&mut self, ids: &[NodeId], letter: &str, t: &[f64]) -> Result<Vec<Pruned>, String> {
        let named = ids.iter().zip(t).enumerate();
        named
            .map(|(i, (&id, &t))| self.one(id, &format!("{letter}{}", i + 1), t))
            .collect()
    }

    /// The upper triangle of M, row i from column i (`[i][k]` is `M_i,i+k`), each element
    /// within its [`mass_tolerance`].
    fn mass(&mut self, m: &[Vec<NodeId>], t: &[f64]) -> Result<Vec<Vec<Pruned>>, String> {
        let mut rows = Vec::with_capacity(m.len());
        for (i, row) in m.iter().enumerate() {
            let mut pruned = Vec::with_capacity(row.len() - i);
            for (j, &id) in row.iter().enumerate().skip(i) {
                let tolerance = mass_tolerance(t, &self.request.envelope, i, j);
                pruned.push(self.one(id, &format!("D{}{}", i + 1, j + 1), tolerance)?);
            }
            rows.push(pruned);
        }
        Ok(rows)
    }
}
