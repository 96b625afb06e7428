//! The simplified models' stage (opt-in, `simplify(...)`): after the trace, each element of
//! the outputs of [`OUTPUTS`] (τ, M, C q̇ and g, one row per method of the family) is expanded
//! into its exact folded polynomial ([`crate::poly`]), the terms whose summed interval bound
//! over the envelope stays within the element's tolerance are dropped ([`prune`], whose bound
//! `dynamics inspect --simplified` prints with the terms), and what is kept is factored back
//! into the graph (`horner`), where the emission finds it as the outputs of the family
//! `Simplified` ([`SimplifiedEquations`], rows keyed by method).
//!
//! Tolerances: `τ_i` and `g_i` within the joint's `t_i`; `M_ij` within
//! `min(t_i, t_j) / Σ_k a_k` (`a` the envelope's accelerations), so that the torque error of
//! the pruned `M q̈` stays within `t_i` too.
//!
//! An output whose pruned elements would keep more than `MAX_KEPT` terms, or whose expansion
//! takes more than `MAX_WORK` term operations, is left exact instead (its
//! [`Fallback`](crate::trace::Fallback) says why, in the method's rustdoc and in `dynamics
//! stats --simplified`): its `_simplified` method computes the exact output, bound 0, and the
//! other outputs are still pruned. A refusal of the whole request would lose the outputs that do simplify (the Panda's
//! g and M beside its τ); stable proc macros have no warnings, so the rustdoc is where the user
//! reads it.

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod bound;
pub mod eval;
mod horner;
mod outputs;
mod prune;

pub use bound::{max_abs_cos, max_abs_sin};
pub use outputs::{prune_outputs, Caps, Output, Pruned, PrunedOutput, OUTPUTS};
pub use prune::{mass_tolerance, prune, Bounded, Pruning};

use crate::method::Family;
use crate::model::Simplification;
use crate::symbolic::NodeId;
use crate::trace::{Elements, Equations, PrunedElement, Shape};
use crate::trace::{SimplifiedEquations, SimplifiedOutput};
use horner::Builder;

/// Most terms a pruned output (all its elements) may keep. Past it the expanded form costs
/// several times the exact recursive one, and one function of thousands of `let`s overflows
/// the stack of rustc's debug-info pass (a 6-joint random arm's τ keeping 3867 terms did).
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub const MAX_KEPT: usize = 1500;

/// Most term operations (see [`crate::trace::Fallback::TooMuchWork`]) the expansion of one
/// output may take. The derive runs in every build of the user's crate, unoptimized unless the crate says
/// otherwise, so the work of a request must stay within seconds there; an output that needs
/// more is far past `MAX_KEPT` anyway. The figures behind the value are in `docs/design/simplified.md`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub const MAX_WORK: u64 = 10_000_000;

/// The derive's caps on each output.
const DERIVE: Caps = Caps {
    kept: MAX_KEPT,
    work: MAX_WORK,
};

/// Builds the pruned τ, M, C q̇ and g of `eq` for `request` into its graph and adds the family
/// `Simplified` to its families. An output too large to prune (see the module's
/// documentation) is the exact one, with its [`Fallback`](crate::trace::Fallback).
///
/// # Errors
/// A request whose lists are not one value per joint, an output that is not a polynomial in
/// the joint variables, or a parameter of the robot (a struct field) in an output or an angle
/// offset: no envelope bounds it.
pub fn add(eq: &mut Equations, request: &Simplification) -> Result<(), String> {
    let pruned = prune_outputs(eq, request, DERIVE)?;
    let exact: Vec<Elements<NodeId>> = OUTPUTS
        .iter()
        .map(|o| elements(o.exact.shape(eq)))
        .collect();
    let mut builder = Builder::new(&mut eq.graph);
    let mut outputs = Vec::with_capacity(pruned.len());
    for (p, exact) in pruned.into_iter().zip(exact) {
        outputs.push(build(&mut builder, p, exact, request)?);
    }
    eq.simplified = Some(SimplifiedEquations {
        request: request.clone(),
        outputs,
    });
    eq.families = eq.families.with(Family::Simplified);
    Ok(())
}

/// The node ids of an exact output.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn elements(shape: Shape<'_>) -> Elements<NodeId> {
    match shape {
        Shape::Vector(v) => Elements::Vector(v.to_vec()),
        Shape::Matrix(m) => Elements::Matrix(m.to_vec()),
        _ => unreachable!("the family prunes vectors and M"),
    }
}

/// One output built into the graph: its kept terms factored, or its `exact` elements where it
/// fell back.
fn build(
    builder: &mut Builder<'_>,
    pruned: PrunedOutput,
    exact: Elements<NodeId>,
    request: &Simplification,
) -> Result<SimplifiedOutput, String> {
    let PrunedOutput { output, elements } = pruned;
    let t = &request.tolerance;
    let (elements, bounds, fallback) = match (elements, exact) {
        (Ok(pruned), Elements::Vector(_)) => {
            let ids = pruned.iter().map(|p| builder.build(&p.pruning.kept));
            let bounds = pruned.iter().map(|p| element(&p.pruning)).collect();
            (
                Elements::Vector(ids.collect::<Result<_, _>>()?),
                Elements::Vector(bounds),
                None,
            )
        }
        (Ok(pruned), Elements::Matrix(m)) => {
            let n = m.len();
            let mut ids = vec![vec![NodeId(0); n]; n];
            let mut bounds = vec![vec![unpruned(0.0); n]; n];
            for p in &pruned {
                let (i, j) = (p.row, p.column.unwrap_or(p.row));
                let id = builder.build(&p.pruning.kept)?;
                (ids[i][j], ids[j][i]) = (id, id);
                (bounds[i][j], bounds[j][i]) = (element(&p.pruning), element(&p.pruning));
            }
            (Elements::Matrix(ids), Elements::Matrix(bounds), None)
        }
        (Err(f), Elements::Vector(ids)) => {
            let bounds = t.iter().map(|&t| unpruned(t)).collect();
            (Elements::Vector(ids), Elements::Vector(bounds), Some(f))
        }
        (Err(f), Elements::Matrix(ids)) => {
            let n = ids.len();
            let tolerance = |i, j| mass_tolerance(t, &request.envelope, i, j);
            let bounds = (0..n).map(|i| (0..n).map(|j| unpruned(tolerance(i, j))).collect());
            (
                Elements::Matrix(ids),
                Elements::Matrix(bounds.collect()),
                Some(f),
            )
        }
    };
    Ok(SimplifiedOutput {
        method: output.method,
        exact: output.exact,
        letter: output.letter,
        elements,
        bounds,
        fallback,
    })
}

/// The bound of a pruned element.
fn element(p: &Pruning) -> PrunedElement {
    PrunedElement {
        bound: p.bound,
        tolerance: p.tolerance,
        terms: p.full.len(),
        kept: p.kept.len(),
    }
}

/// An element of an output left exact: nothing dropped, nothing counted.
fn unpruned(tolerance: f64) -> PrunedElement {
    PrunedElement {
        bound: 0.0,
        tolerance,
        terms: 0,
        kept: 0,
    }
}
