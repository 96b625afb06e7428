//! The gravity torques `g(q) = ∂P/∂q` (the book's D_i, eq. 6.45), with the springs' torques.
//!
//! Two candidates: Newton-Euler at rest (`τ` with `q̇ = q̈ = 0`), and the composite bodies'
//! first moments ([`algo::gravity_torques`]), which carry the gravity vector out and the
//! composites in side by side, a shorter chain of products. On a tie the composites.

use super::cost::{cheapest, ids};
use super::expr::Expr;
use super::joints::JointTerms;
use crate::algo::{self, Chain, V3};
use crate::symbolic::{Graph, NodeId};
use std::cell::RefCell;

/// The cheapest `g(q)` of the candidates, springs included.
pub(super) fn gravity<'g>(
    graph: &'g RefCell<Graph>,
    chain: &Chain<Expr<'g>>,
    gravity: V3<Expr<'g>>,
    joints: &JointTerms<'g>,
) -> Vec<NodeId> {
    let zeros = joints.zeros();
    let by_composites = joints.with_springs(algo::gravity_torques(chain, gravity));
    let by_newton_euler = joints.with_springs(algo::rnea(chain, &zeros, &zeros, gravity));
    let best = cheapest(&graph.borrow(), by_composites, [by_newton_euler], |g| {
        ids(g)
    });
    ids(&best)
}
