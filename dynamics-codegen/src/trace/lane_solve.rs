//! The forward dynamics' derivatives in lanes of tangents: `∂q̈/∂x = −M⁻¹ ∂τ/∂x` at the forward
//! dynamics' `q̈`, with `∂τ/∂x` from the plan of `∂τ`'s tangents ([`Graph::tangents`]) and the
//! solve as row operations on those lanes.
//!
//! A row of `∂τ/∂x` is the tangent of `τ_i`, a vector of the n directions, so the LDLᵀ solve
//! with M's factors ([`algo::Ldlt`]) takes whole rows at once: `y_i = b_i − Σ_{k<i} L_ik y_k`,
//! then `x_i = −y_i / d_i − Σ_{k>i} L_ki x_k`, each step a vector times a scalar added to a
//! vector, n directions in one operation instead of one solve per column. The steps are lanes
//! of the same plan ([`Lane`]), which the emitters write as they write the tangents. A tree's
//! factors from the tips solve in reverse order; their zeros cost nothing.

use crate::algo;
use crate::symbolic::{Graph, Lane, NodeId, Of, Tangents, Term, Var};
use std::collections::HashMap;

/// `plan` (of τ's tangents, its factors read at `Var::Qdd`) with each factor evaluated at the
/// forward dynamics' `q̈` instead, `qdd[i]` for `Var::Qdd(i)`: `∂τ/∂x` at fixed `q̈`, read where
/// `q̈` is the forward dynamics'. A lane is computed once its factors and lanes are, the
/// substituted factors being new nodes.
pub(super) fn at_qdd(plan: &Tangents, graph: &mut Graph, qdd: &[NodeId]) -> Tangents {
    let factors = plan.factors();
    let substituted = graph.substitute(&factors, |v| match v {
        Var::Qdd(i) => qdd.get(usize::from(i)).copied(),
        _ => None,
    });
    let map: HashMap<NodeId, NodeId> = factors.into_iter().zip(substituted).collect();
    let mut lanes: Vec<Lane> = Vec::with_capacity(plan.lanes.len());
    for lane in &plan.lanes {
        let terms: Vec<Term> = lane
            .terms
            .iter()
            .map(|t| Term {
                factors: t.factors.iter().map(|f| map[f]).collect(),
                ..t.clone()
            })
            .collect();
        let after = due(&lanes, &terms);
        lanes.push(Lane { after, terms });
    }
    Tangents {
        lanes,
        ..plan.clone()
    }
}

/// `−M⁻¹ B`, B's rows the outputs of `plan` (a row `None` is zero), with M's `factors`: the
/// plan with the solve's lanes appended, its outputs the rows of the solution.
pub(super) fn solve_negated(
    plan: Tangents,
    factors: &algo::Ldlt<NodeId>,
    graph: &Graph,
) -> Tangents {
    let rows: Vec<Vec<Term>> = plan
        .outputs
        .iter()
        .map(|row| row.map(|k| lane_term(Of::Lane(k), Vec::new(), false)))
        .map(|term| term.into_iter().collect())
        .collect();
    solve(plan, rows, factors, graph, true)
}

/// `M⁻¹` from M's `factors` as a plan of its own: row i the solution for `e_i`, a lane.
pub(super) fn inverse(factors: &algo::Ldlt<NodeId>, graph: &Graph) -> Tangents {
    let n = factors.pivots.len();
    let rows: Vec<Vec<Term>> = (0..n)
        .map(|j| vec![lane_term(Of::Unit(direction(j)), Vec::new(), false)])
        .collect();
    let plan = Tangents {
        directions: n,
        lanes: Vec::new(),
        outputs: Vec::new(),
        group: crate::symbolic::BLOCK,
    };
    solve(plan, rows, factors, graph, false)
}

/// `± M⁻¹ B` (negated with `negated`), row i of B the sum of `rows[i]`, as lanes appended to
/// `plan`, whose outputs become the solution's rows.
fn solve(
    mut plan: Tangents,
    rows: Vec<Vec<Term>>,
    factors: &algo::Ldlt<NodeId>,
    graph: &Graph,
    negated: bool,
) -> Tangents {
    let n = rows.len();
    // Row i of the factors is joint `at(i)` (reversed for a tree's, factored from the tips).
    let at = |i: usize| if factors.reversed { n - 1 - i } else { i };
    let l = |i: usize, k: usize| Some(factors.lower[i][k]).filter(|&f| !graph.is_zero(f));
    let eliminate =
        |i: usize, k: usize, x: Option<usize>| Some(lane_term(Of::Lane(x?), vec![l(i, k)?], true));
    // L y = B.
    let mut y: Vec<Option<usize>> = Vec::with_capacity(n);
    for i in 0..n {
        let eliminated = (0..i).filter_map(|k| eliminate(i, k, y[k]));
        let terms: Vec<Term> = rows[at(i)].iter().cloned().chain(eliminated).collect();
        y.push(write(&mut plan, terms));
    }
    // Lᵀ x = ± D⁻¹ y, from the last row up.
    let mut x: Vec<Option<usize>> = vec![None; n];
    for i in (0..n).rev() {
        let pivot = factors.inverse_pivots[i];
        let scaled = y[i].map(|y| lane_term(Of::Lane(y), vec![pivot], negated));
        let eliminated = (i + 1..n).filter_map(|k| eliminate(k, i, x[k]));
        let terms: Vec<Term> = scaled.into_iter().chain(eliminated).collect();
        x[i] = write(&mut plan, terms);
    }
    plan.outputs = (0..n).map(|j| x[at(j)]).collect();
    plan
}

/// Direction `j` as a unit vector's index.
fn direction(j: usize) -> u16 {
    u16::try_from(j).unwrap_or(u16::MAX)
}

/// `± Π factors · of`.
pub(super) fn lane_term(of: Of, factors: Vec<NodeId>, negative: bool) -> Term {
    Term {
        of,
        factors,
        negative,
    }
}

/// The lane of the sum of `terms` (`None` for none; a lane itself where it is the only term).
pub(super) fn write(plan: &mut Tangents, terms: Vec<Term>) -> Option<usize> {
    match terms.as_slice() {
        [] => return None,
        [Term {
            of: Of::Lane(k),
            factors,
            negative: false,
        }] if factors.is_empty() => return Some(*k),
        _ => {}
    }
    let after = due(&plan.lanes, &terms);
    plan.lanes.push(Lane { after, terms });
    Some(plan.lanes.len() - 1)
}

/// The node after which a lane of `terms` can be computed: the last of its factors and of the
/// nodes its lanes (in `lanes`) are computed after, so that the emitters, which order the
/// lanes by that node, write each after what it reads.
fn due(lanes: &[Lane], terms: &[Term]) -> NodeId {
    let factors = terms.iter().flat_map(|t| t.factors.iter().copied());
    let read = terms.iter().filter_map(|t| match t.of {
        Of::Lane(k) => Some(lanes[k].after),
        Of::Unit(_) => None,
    });
    factors.chain(read).max().unwrap_or(NodeId(0))
}
