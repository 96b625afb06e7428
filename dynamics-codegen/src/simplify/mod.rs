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
//!
//! An output (τ, M or g) whose pruned elements would keep more than `MAX_KEPT` terms, or
//! whose expansion takes more than `MAX_WORK` term operations, is left exact instead (its
//! [`Fallback`] says why, in the method's rustdoc and in `dynamics stats --simplified`): its
//! `_simplified` method computes the exact output, bound 0, and the other outputs are still
//! pruned. A refusal of the whole request would lose the outputs that do simplify (the Panda's
//! g and M beside its τ); stable proc macros have no warnings, so the rustdoc is where the user
//! reads it.

mod horner;
#[cfg(test)]
mod tests;

use crate::inspect::simplify::{eval, mass_tolerance, prune, Pruning};
use crate::inspect::{Expander, Limits};
use crate::method::Family;
use crate::model::Simplification;
use crate::symbolic::NodeId;
use crate::trace::{Equations, Fallback, PrunedElement, SimplifiedEquations};
use horner::Builder;

/// Most terms a pruned output (all its elements) may keep. Past it the expanded form costs
/// several times the exact recursive one, and one function of thousands of `let`s overflows
/// the stack of rustc's debug-info pass (a 6-joint random arm's τ keeping 3867 terms did).
const MAX_KEPT: usize = 1500;

/// Most term operations (see [`Fallback::TooMuchWork`]) the expansion of one output may take.
/// The derive runs in every build of the user's crate, unoptimized unless the crate says
/// otherwise, so the work of a request must stay within seconds there; an output that needs
/// more is far past `MAX_KEPT` anyway. The figures behind the value are in `docs/design.md`.
const MAX_WORK: u64 = 10_000_000;

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

/// An element of an output left exact: nothing dropped, nothing counted.
fn exact(tolerance: f64) -> PrunedElement {
    PrunedElement {
        bound: 0.0,
        tolerance,
        terms: 0,
        kept: 0,
    }
}

/// Builds the pruned τ, M and g of `eq` for `request` into its graph and adds the family
/// `Simplified` to its families. An output too large to prune (see the module's
/// documentation) is the exact one, with its [`Fallback`].
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
    let t = &request.tolerance;
    let (tau, mass, coriolis, gravity) = {
        let limits = Limits {
            max_terms: usize::MAX,
            max_work: MAX_WORK,
        };
        let mut p = Pruner {
            expander: Expander::new(eq, limits),
            request,
            offsets: &constants.offsets,
        };
        let tau = p.vector(&eq.tau, "T", t)?;
        let gravity = p.vector(&eq.gravity, "D", t)?;
        let coriolis = p.vector(&eq.coriolis_torques, "C", t)?;
        let mass = p.mass(&eq.mass, t)?;
        (tau, mass, coriolis, gravity)
    };
    let mut builder = Builder::new(&mut eq.graph);
    let mut vector = |pruned: Result<Vec<Pruned>, Fallback>, exact_ids: &[NodeId]| {
        Ok::<_, String>(match pruned {
            Ok(p) => {
                let ids = p.iter().map(|p| builder.build(&p.pruning.kept));
                let ids = ids.collect::<Result<_, _>>()?;
                (ids, p.iter().map(Pruned::element).collect(), None)
            }
            Err(f) => (
                exact_ids.to_vec(),
                t.iter().map(|&t| exact(t)).collect(),
                Some(f),
            ),
        })
    };
    let (tau_ids, tau_bounds, tau_fallback) = vector(tau, &eq.tau)?;
    let (gravity_ids, gravity_bounds, gravity_fallback) = vector(gravity, &eq.gravity)?;
    let (coriolis_ids, coriolis_bounds, coriolis_fallback) =
        vector(coriolis, &eq.coriolis_torques)?;
    let (mass, mass_bounds, mass_fallback) = match mass {
        Ok(rows) => {
            let mut ids = vec![vec![NodeId(0); n]; n];
            for (i, row) in rows.iter().enumerate() {
                for (k, p) in row.iter().enumerate() {
                    let id = builder.build(&p.pruning.kept)?;
                    ids[i][i + k] = id;
                    ids[i + k][i] = id;
                }
            }
            let element = |i: usize, j: usize| rows[i.min(j)][i.abs_diff(j)].element();
            let bounds = (0..n).map(|i| (0..n).map(|j| element(i, j)).collect());
            (ids, bounds.collect(), None)
        }
        Err(f) => {
            let tolerance = |i, j| mass_tolerance(t, &request.envelope, i, j);
            let bounds = (0..n).map(|i| (0..n).map(|j| exact(tolerance(i, j))).collect());
            (eq.mass.clone(), bounds.collect(), Some(f))
        }
    };
    eq.simplified = Some(SimplifiedEquations {
        request: request.clone(),
        tau: tau_ids,
        mass,
        coriolis_torques: coriolis_ids,
        gravity: gravity_ids,
        tau_bounds,
        mass_bounds,
        coriolis_torques_bounds: coriolis_bounds,
        gravity_bounds,
        tau_fallback,
        mass_fallback,
        coriolis_torques_fallback: coriolis_fallback,
        gravity_fallback,
    });
    eq.families = eq.families.with(Family::Simplified);
    Ok(())
}

/// Expands and prunes output elements over one request, an output at a time, each within the
/// caps `MAX_KEPT` and `MAX_WORK`.
struct Pruner<'a> {
    expander: Expander<'a>,
    request: &'a Simplification,
    offsets: &'a [f64],
}

/// The terms an output's elements keep, so far.
struct Count(usize);

impl Count {
    /// Adds `p`'s kept terms; the fallback once past the cap.
    fn add(&mut self, p: &Pruned) -> Result<(), Fallback> {
        self.0 += p.pruning.kept.len();
        if self.0 > MAX_KEPT {
            return Err(Fallback::TooManyTerms {
                kept: self.0,
                cap: MAX_KEPT,
            });
        }
        Ok(())
    }
}

/// An output pruned element by element, or why it is left exact.
type Output<T> = Result<T, Fallback>;

impl Pruner<'_> {
    /// Element `id`, named `name` in errors, pruned within `tolerance`; `Ok(None)` when the
    /// output's budget of work ran out first.
    fn one(&mut self, id: NodeId, name: &str, tolerance: f64) -> Result<Option<Pruned>, String> {
        let Some(full) = self.expander.folded(id) else {
            if self.expander.exhausted() {
                return Ok(None);
            }
            return Err(format!("{name} is not a polynomial in the joint variables"));
        };
        let pruning = prune(full, &self.request.envelope, self.offsets, tolerance)
            .map_err(|e| format!("{name}: {e}"))?;
        Ok(Some(Pruned { pruning }))
    }

    /// Element `id` of an output that has kept `count` terms so far.
    fn counted(
        &mut self,
        id: NodeId,
        name: &str,
        tolerance: f64,
        count: &mut Count,
    ) -> Result<Output<Pruned>, String> {
        Ok(match self.one(id, name, tolerance)? {
            Some(p) => count.add(&p).map(|()| p),
            None => Err(Fallback::TooMuchWork { budget: MAX_WORK }),
        })
    }

    /// A vector of elements, `T1`, `T2`, …, each within its joint's tolerance.
    fn vector(
        &mut self,
        ids: &[NodeId],
        letter: &str,
        t: &[f64],
    ) -> Result<Output<Vec<Pruned>>, String> {
        self.expander.renew_budget();
        let mut count = Count(0);
        let mut out = Vec::with_capacity(ids.len());
        for (i, (&id, &t)) in ids.iter().zip(t).enumerate() {
            let name = format!("{letter}{}", i + 1);
            match self.counted(id, &name, t, &mut count)? {
                Ok(p) => out.push(p),
                Err(f) => return Ok(Err(f)),
            }
        }
        Ok(Ok(out))
    }

    /// The upper triangle of M, row i from column i (`[i][k]` is `M_i,i+k`), each element
    /// within its [`mass_tolerance`].
    fn mass(&mut self, m: &[Vec<NodeId>], t: &[f64]) -> Result<Output<Vec<Vec<Pruned>>>, String> {
        self.expander.renew_budget();
        let mut count = Count(0);
        let mut rows = Vec::with_capacity(m.len());
        for (i, row) in m.iter().enumerate() {
            let mut pruned = Vec::with_capacity(row.len() - i);
            for (j, &id) in row.iter().enumerate().skip(i) {
                let tolerance = mass_tolerance(t, &self.request.envelope, i, j);
                let name = format!("D{}{}", i + 1, j + 1);
                match self.counted(id, &name, tolerance, &mut count)? {
                    Ok(p) => pruned.push(p),
                    Err(f) => return Ok(Err(f)),
                }
            }
            rows.push(pruned);
        }
        Ok(Ok(rows))
    }
}
