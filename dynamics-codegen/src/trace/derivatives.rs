//! The derivatives of the dynamics, for model-predictive control (opt-in: traced only for a
//! robot that asks for them, [`Equations::add_derivatives`]).
//!
//! * `∂τ/∂q`: column j is the forward derivative of τ's traced graph by `q_j`
//!   (`∂ sin q_j/∂q_j = cos q_j`), at compile time;
//! * `∂τ/∂q̇`: the cheaper of that graph's derivative by `q̇_j` and `2 C + ∂f/∂q̇`, since with
//!   the Christoffel symbols `∂(C q̇)_i/∂q̇_j = 2 Σ_k Γ_ijk q̇_k = 2 C_ij` (Γ_ijk = Γ_ikj);
//! * where the build computes tangents in lanes (`Real::TANGENTS_IN_LANES`: AVX-512), both
//!   `∂τ/∂q` and `∂τ/∂q̇` from one vector of tangents per node of τ's graph, all n directions
//!   at once ([`Graph::tangents`]), instead of the two above;
//! * `∂q̈/∂x = −M⁻¹ ∂τ/∂x` at the forward dynamics' `q̈` (Carpentier and Mansard, RSS 2018):
//!   `∂τ/∂q` with each `q̈_i` replaced by that `q̈_i`, solved column by column with the LDLᵀ of
//!   M that the forward dynamics factored; `∂q̈/∂τ = M⁻¹`;
//! * where the build computes tangents in lanes, `∂q̈/∂q` and `∂q̈/∂q̇` from the same plan as
//!   `∂τ`'s, its factors at that `q̈`, and the solve on the lanes, a row of n directions a step
//!   (`lane_solve`), and `M⁻¹` the same solve of the identity's rows.

use super::cost::{cheapest, flat};
use super::expr::Expr;
use super::lane_solve;
use super::tracer::joint_index;
use super::Equations;
use crate::method::Family;
use crate::symbolic::{Graph, NodeId, Number, Tangents, Var, Wrt, QUARTER_BLOCK};
use std::cell::RefCell;

/// The scalar factors a term of `∂q̈`'s tangents may carry before its vector is written out
/// ([`Graph::tangents_with`]); `∂τ`'s carry two. `∂q̈`'s function holds the forward dynamics'
/// scalars beside the tangents, and a product of two factors computed once into a vector
/// (one more lane operation) costs less there than the scalar product at each reader with its
/// broadcast and its spill: in a probe crate (AVX-512, docs/performance.md, 2026-11-30) one
/// factor took the Panda's `forward_dynamics_derivatives` from 35.3 to 33.8 kB and 8-9 % less
/// time, random5's and PUMA 560's 6-8 % less.
const SOLVED_FACTORS: usize = 1;

/// The derivatives' outputs: node ids into [`Equations::graph`].
#[derive(Clone, Debug)]
pub struct DerivativeEquations {
    /// `[∂τ/∂q, ∂τ/∂q̇]`, n × n each, row i the derivatives of `τ_i`.
    pub inverse: Vec<Vec<Vec<NodeId>>>,
    /// Per matrix of `inverse`, the plan that computes it in lanes instead, where taken.
    pub inverse_lanes: Vec<Option<Tangents>>,
    /// `q̈` of the forward dynamics (leaves [`Var::Tau`]).
    pub qdd: Vec<NodeId>,
    /// `[∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ]`, n × n each.
    pub forward: Vec<Vec<Vec<NodeId>>>,
    /// Per matrix of `forward`, the plan that computes it in lanes instead, where taken.
    pub forward_lanes: Vec<Option<Tangents>>,
}

impl Equations {
    /// Traces the derivatives ([`Equations::derivatives`]) into the graph, after every other
    /// output, so that those keep their nodes.
    pub fn add_derivatives(&mut self) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let inverse = inverse_derivatives(self, &graph);
        let forward = forward_derivatives(self, &graph, &inverse);
        self.graph = graph.into_inner();
        let inverse_lanes = inverse_lanes(self);
        let forward_lanes = forward_lanes(self, &inverse_lanes);
        self.derivatives = Some(DerivativeEquations {
            inverse,
            inverse_lanes,
            qdd: self.forward.qdd.clone(),
            forward,
            forward_lanes,
        });
        self.families = self.families.with(Family::Derivatives);
    }
}

/// `[∂τ/∂q, ∂τ/∂q̇]` as matrices of nodes.
fn inverse_derivatives(eq: &Equations, graph: &RefCell<Graph>) -> Vec<Vec<Vec<NodeId>>> {
    let n = eq.dof;
    let mut g = graph.borrow_mut();
    let columns = |g: &mut Graph, wrt: fn(u16) -> Wrt| -> Vec<Vec<NodeId>> {
        let columns: Vec<Vec<NodeId>> = (0..n)
            .map(|j| g.derivative_by(&eq.tau, wrt(joint_index(j))))
            .collect();
        transpose(&columns)
    };
    let by_q = columns(&mut g, Wrt::Position);
    let traced = columns(&mut g, Wrt::Velocity);
    let two = g.num(Number::int(2));
    let from_coriolis: Vec<Vec<NodeId>> = (0..n)
        .map(|i| {
            let slope = g.derivative_by(&[eq.friction[i]], Wrt::Velocity(joint_index(i)))[0];
            (0..n)
                .map(|j| {
                    let c = g.mul(two, eq.coriolis[i][j]);
                    if i == j {
                        g.add(c, slope)
                    } else {
                        c
                    }
                })
                .collect()
        })
        .collect();
    // Counted with ∂τ/∂q, which the same function computes.
    let with_by_q = |by_qd: &Vec<Vec<NodeId>>| [flat(&by_q), flat(by_qd)].concat();
    let by_qd = cheapest(&g, traced, [from_coriolis], with_by_q);
    vec![by_q, by_qd]
}

/// The plans of `[∂τ/∂q, ∂τ/∂q̇]` in lanes ([`Graph::tangents`]), which the code takes where
/// the build computes tangents in lanes; `None` where a tangent needs a node the graph
/// lacks (`∂q̇` of smoothed friction's `tanh`), which is then computed as above. Each in
/// blocks of four directions where those cost less ([`Tangents::prefer_groups_of_four`]).
fn inverse_lanes(eq: &Equations) -> Vec<Option<Tangents>> {
    let n = eq.dof;
    [Wrt::Position(0), Wrt::Velocity(0)]
        .map(|wrt| {
            let mut plan = eq.graph.tangents(&eq.tau, wrt, n)?;
            if plan.prefer_groups_of_four() {
                plan.group = QUARTER_BLOCK;
            }
            Some(plan)
        })
        .into()
}

/// The plans of `[∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ]` in lanes: `∂τ`'s tangents at the forward dynamics'
/// `q̈`, then the solve with M's factors (`lane_solve`), `None` where `∂τ`'s plan is; `M⁻¹`
/// solved for the identity's rows. `∂τ`'s tangents planned again with one scalar factor to a
/// term ([`SOLVED_FACTORS`]) and in blocks of eight, as they were measured.
fn forward_lanes(eq: &mut Equations, inverse: &[Option<Tangents>]) -> Vec<Option<Tangents>> {
    let n = eq.dof;
    let (graph, qdd, factors) = (&mut eq.graph, &eq.forward.qdd, &eq.forward.factors);
    let mut planned: Vec<Option<Tangents>> = inverse
        .iter()
        .zip([Wrt::Position(0), Wrt::Velocity(0)])
        .map(|(plan, wrt)| {
            plan.as_ref()?;
            let plan = graph.tangents_with(&eq.tau, wrt, n, SOLVED_FACTORS)?;
            let at_qdd = lane_solve::at_qdd(&plan, graph, qdd);
            Some(lane_solve::solve_negated(at_qdd, factors, graph))
        })
        .collect();
    planned.push(Some(lane_solve::inverse(factors, graph)));
    planned
}

/// `[∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ]` at the forward dynamics' `q̈`, from `inverse`, `[∂τ/∂q, ∂τ/∂q̇]`.
pub(super) fn forward_derivatives(
    eq: &Equations,
    graph: &RefCell<Graph>,
    inverse: &[Vec<Vec<NodeId>>],
) -> Vec<Vec<Vec<NodeId>>> {
    let qdd = &eq.forward.qdd;
    let at_qdd = |m: &[Vec<NodeId>]| -> Vec<Vec<NodeId>> {
        let mut g = graph.borrow_mut();
        m.iter()
            .map(|row| {
                g.substitute(row, |v| match v {
                    Var::Qdd(i) => qdd.get(usize::from(i)).copied(),
                    _ => None,
                })
            })
            .collect()
    };
    let factors = eq.forward.factors_in(graph);
    let solve_negated = |m: &[Vec<NodeId>]| -> Vec<Vec<NodeId>> {
        let rhs: Vec<Vec<Expr>> = m
            .iter()
            .map(|row| row.iter().map(|&id| -Expr::new(graph, id)).collect())
            .collect();
        let x = factors.solve_columns(&rhs);
        x.iter()
            .map(|row| row.iter().map(|e| e.id()).collect())
            .collect()
    };
    let by_q = solve_negated(&at_qdd(&inverse[0]));
    let by_qd = solve_negated(&at_qdd(&inverse[1]));
    vec![by_q, by_qd, eq.forward.mass_inverse.clone()]
}

/// The rows of a matrix given by its columns.
pub(super) fn transpose(columns: &[Vec<NodeId>]) -> Vec<Vec<NodeId>> {
    let rows = columns.first().map_or(0, Vec::len);
    (0..rows)
        .map(|i| columns.iter().map(|column| column[i]).collect())
        .collect()
}
