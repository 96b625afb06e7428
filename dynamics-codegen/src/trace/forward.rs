//! Forward dynamics, `q̈ = M⁻¹(τ − C q̇ − g − f(q̇))`, and `M⁻¹`, through the unrolled LDLᵀ of
//! M ([`algo::Ldlt`]) traced on the graph where M already is, or for a kinematic tree
//! Featherstone's `Lᵀ D L`, which keeps M's zeros. The factors depend on the
//! parameters and `q` alone: in the forward family's module they go to its shared
//! configuration, and each method adds only its right-hand side and the substitutions.

use super::expr::Expr;
use crate::algo;
use crate::symbolic::{Graph, NodeId, Var};
use std::cell::RefCell;

/// The forward dynamics' outputs.
#[derive(Clone, Debug)]
pub struct ForwardEquations {
    /// `M = L D Lᵀ`, as node ids: M is positive definite where every pivot is positive. Other
    /// outputs solving with M trace on these ([`ForwardEquations::factors_in`]).
    pub factors: algo::Ldlt<NodeId>,
    /// `M⁻¹`, n × n.
    pub mass_inverse: Vec<Vec<NodeId>>,
    /// `q̈` for the joint torques `τ` (leaves [`Var::Tau`]), through the factors: what other
    /// outputs solving with M build on.
    pub qdd: Vec<NodeId>,
    /// What `forward_dynamics` returns: `q̈` and the pivots it checks, all positive where M is
    /// positive definite. [`ForwardEquations::qdd`] and the factors' pivots, or on a floating
    /// base the articulated-body algorithm's where it takes fewer operations
    /// ([`algo::floating_aba`]).
    pub returned: (Vec<NodeId>, Vec<NodeId>),
}

impl ForwardEquations {
    /// The factors as expressions of `graph`, to solve further right-hand sides with
    /// ([`algo::Ldlt::solve`], [`algo::Ldlt::solve_columns`]).
    #[must_use]
    pub fn factors_in<'g>(&self, graph: &'g RefCell<Graph>) -> algo::Ldlt<Expr<'g>> {
        self.factors.map(|id| Expr::new(graph, id))
    }
}

/// Traces the factorization of `mass` and the solutions; `bias` is `C q̇ + g` and `friction`
/// the friction torques; `tree` factors from the tips ([`algo::Ldlt::from_the_tips`]).
pub(super) fn forward(
    graph: &RefCell<Graph>,
    mass: &[Vec<NodeId>],
    bias: &[NodeId],
    friction: &[NodeId],
    tree: bool,
) -> ForwardEquations {
    let expr = |id: NodeId| Expr::new(graph, id);
    let m: Vec<Vec<Expr>> = mass
        .iter()
        .map(|row| row.iter().map(|&id| expr(id)).collect())
        .collect();
    // A tree's M factored from the tips keeps its zeros (Featherstone's Lᵀ D L).
    let factors = if tree {
        algo::Ldlt::from_the_tips(&m)
    } else {
        algo::Ldlt::new(&m)
    };
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
            let tau = expr(
                graph
                    .borrow_mut()
                    .var(Var::Tau(u16::try_from(i).unwrap_or(u16::MAX))),
            );
            tau - expr(b) - expr(f)
        })
        .collect();
    let qdd: Vec<NodeId> = factors.solve(&rhs).iter().map(|e| e.id()).collect();
    let factors = factors.map(Expr::id);
    ForwardEquations {
        returned: (qdd.clone(), factors.pivots.clone()),
        factors,
        mass_inverse,
        qdd,
    }
}
