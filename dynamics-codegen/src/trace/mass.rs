//! The mass matrix `M(q)` (the book's D_ij, eq. 6.43) by the composite rigid body algorithm
//! ([`algo::crba`]) on the regrouped chain, and the chain the other outputs are traced on.
//!
//! The candidates differ only in how the trace is arranged, not in the value:
//! * bodies carried through a general twist moved to the parent's origin after the twist or
//!   before it ([`Chain::moving_before_twist`]): which is shorter depends on the twists and
//!   offsets; with quarter-turn twists the two are the same graph;
//! * moments carried joint by joint or through the sums of the angles of parallel joints
//!   ([`Chain::summing_angles`]), which saves where a robot has such runs.

use super::cost::{cheapest, flat, matrix_ids};
use super::expr::Expr;
use crate::algo::{self, Chain};
use crate::symbolic::Graph;
use std::cell::RefCell;

/// A chain and `M` traced on it.
type Traced<'g> = (Chain<Expr<'g>>, Vec<Vec<Expr<'g>>>);

/// The cheapest `M` of the candidates (actuator inertia not added), with the regrouped chain
/// it was traced on.
pub(super) fn mass_matrix<'g>(graph: &'g RefCell<Graph>, chain: &Chain<Expr<'g>>) -> Traced<'g> {
    let moved_after_twist = by_crba(graph, chain.regrouped());
    let moved_before_twist = by_crba(graph, chain.clone().moving_before_twist(true).regrouped());
    cheapest(
        &graph.borrow(),
        moved_after_twist,
        [moved_before_twist],
        |(_, m)| flat(&matrix_ids(m)),
    )
}

/// `M` on `chain`, its moments carried joint by joint or through sums of angles, whichever
/// is cheaper.
fn by_crba<'g>(graph: &'g RefCell<Graph>, chain: Chain<Expr<'g>>) -> Traced<'g> {
    let joint_by_joint = algo::crba(&chain);
    let summed = chain.clone().summing_angles(true);
    let by_sums = summed.has_runs().then(|| algo::crba(&summed));
    let m = cheapest(&graph.borrow(), joint_by_joint, by_sums, |m| {
        flat(&matrix_ids(m))
    });
    (chain, m)
}
