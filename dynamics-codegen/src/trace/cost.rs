//! The cost measure behind every route choice: the additions, multiplications and negations
//! that computing a set of outputs takes, shared subexpressions counted once. The emitted code
//! computes exactly those nodes, so the cheaper route is the faster code.

use super::expr::Expr;
use crate::symbolic::{Graph, Node, NodeId};

/// The additions, multiplications and negations that computing `outputs` takes.
pub(super) fn operations(g: &Graph, outputs: &[NodeId]) -> usize {
    let live = g.live(outputs);
    g.nodes()
        .filter(|(id, node)| {
            live[id.index()] && matches!(node, Node::Add(..) | Node::Mul(..) | Node::Neg(_))
        })
        .count()
}

/// Of ways to compute the same outputs, `first` and `others`, the one whose `outputs` take
/// the fewest operations; the earliest on a tie.
pub(super) fn cheapest<T>(
    g: &Graph,
    first: T,
    others: impl IntoIterator<Item = T>,
    outputs: impl Fn(&T) -> Vec<NodeId>,
) -> T {
    let cost = |candidate: &T| operations(g, &outputs(candidate));
    let first_cost = cost(&first);
    let (best, _) = others
        .into_iter()
        .fold((first, first_cost), |(best, best_cost), candidate| {
            let candidate_cost = cost(&candidate);
            if candidate_cost < best_cost {
                (candidate, candidate_cost)
            } else {
                (best, best_cost)
            }
        });
    best
}

/// The nodes of traced values.
pub(super) fn ids(v: &[Expr]) -> Vec<NodeId> {
    v.iter().map(|e| e.id()).collect()
}

/// The nodes of a traced matrix, row by row.
pub(super) fn matrix_ids(m: &[Vec<Expr>]) -> Vec<Vec<NodeId>> {
    m.iter().map(|r| ids(r)).collect()
}

/// The entries of a matrix of nodes, row by row.
pub(super) fn flat(m: &[Vec<NodeId>]) -> Vec<NodeId> {
    m.iter().flatten().copied().collect()
}
