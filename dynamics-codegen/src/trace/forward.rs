//! Forward dynamics, `q̈ = M⁻¹(τ − C q̇ − g − f(q̇))`, and `M⁻¹`, through the unrolled LDLᵀ of
//! M ([`algo::ldlt`]) traced on the graph where M already is: the factorization depends on the
//! parameters and `q` alone, so it is shared code, and a method adds only its right-hand side
//! and the two substitutions.

use crate::algo::{self, Scalar};
use crate::symbolic::{Expr, Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The forward dynamics' outputs.
#[derive(Clone, Debug)]
pub struct ForwardEquations {
    /// The pivots of `M = L D Lᵀ`: M is positive definite when all are positive.
    pub pivots: Vec<NodeId>,
    /// `M⁻¹`, n × n.
    pub mass_inverse: Vec<Vec<NodeId>>,
    /// `q̈` for the joint torques `τ` (leaves [`Var::Tau`]).
    pub qdd: Vec<NodeId>,
}

/// Traces the factorization of `mass` and the solutions; `bias` is `C q̇ + g` and `friction`
/// the friction torques.
pub(super) fn forward<'g>(
    graph: &'g RefCell<Graph>,
    mass: &[Vec<NodeId>],
    bias: &[NodeId],
    friction: &[NodeId],
) -> ForwardEquations {
    let expr = |id: NodeId| -> Expr<'g> { Expr::new(graph, id) };
    let m: Vec<Vec<Expr>> = mass
        .iter()
        .map(|row| row.iter().map(|&id| expr(id)).collect())
        .collect();
    // A constant zero pivot has no reciprocal: its zero stands in, and the check fails.
    let recip = |x: Expr<'g>| -> Expr<'g> {
        let r = graph.borrow_mut().recip(x.id());
        r.map_or_else(|| x.constant(Number::ZERO), expr)
    };
    let factors = algo::ldlt(&m, recip);
    let mass_inverse = factors
        .inverse()
        .iter()
        .map(|row| row.iter().map(|e| e.id()).collect())
        .collect();
    let rhs: Vec<Expr> = bias
        .iter()
        .zip(friction)
        .enumerate()
        .map(|(i, (&b, &f))| {
            let tau = graph
                .borrow_mut()
                .var(Var::Tau(u16::try_from(i).unwrap_or(u16::MAX)));
            expr(tau) - expr(b) - expr(f)
        })
        .collect();
    ForwardEquations {
        pivots: factors.pivots.iter().map(|e| e.id()).collect(),
        mass_inverse,
        qdd: factors.solve(&rhs).iter().map(|e| e.id()).collect(),
    }
}
