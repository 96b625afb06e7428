//! The Christoffel symbols of the first kind (the book's D_ijk, eq. 6.44)
//! `Γ_ijk = ½(∂M_ij/∂q_k + ∂M_ik/∂q_j − ∂M_jk/∂q_i)` and the Coriolis matrix
//! `C_ij = Σ_k Γ_ijk q̇_k`, with `Ṁ = C + Cᵀ`.
//!
//! Five candidates for `C`, of which the cheapest is kept:
//! * `∂M/∂q_k` by differentiating `M`'s graph, or for a revolute joint by differentiating the
//!   composite rigid body algorithm ([`algo::crba_derivative`]), which reuses the turned
//!   values where the graph's derivative multiplies by sines and cosines again; the cheaper
//!   depends on the robot;
//! * for each, `C` summed over the symbols, or as `½(Ṁ_ij + P_ij − P_ji)` with
//!   `P_ij = Σ_k ∂M_ik/∂q_j q̇_k`, the same terms without forming the n³ symbols;
//! * `C` carried down the chain in O(n²) ([`algo::coriolis_matrix`]), without the derivatives
//!   of `M`: it wins on long chains. The symbols are then those of the cheapest of the four.

use super::cost::{cheapest, flat, ids, matrix_ids};
use super::expr::Expr;
use super::tracer::joint_index;
use crate::algo::{self, Chain};
use crate::symbolic::{Graph, NodeId, Number};
use std::cell::RefCell;

/// `Γ_ijk` as `christoffel[i][j][k]`.
type Christoffel = Vec<Vec<Vec<NodeId>>>;

/// The symbols and `C` of the cheapest candidate.
pub(super) fn coriolis<'g>(
    graph: &'g RefCell<Graph>,
    chain: &Chain<Expr<'g>>,
    mass: &[Vec<NodeId>],
    qd: &[Expr<'g>],
    half: NodeId,
) -> (Christoffel, Vec<Vec<NodeId>>) {
    let n = mass.len();
    let analytic: Vec<Option<Vec<NodeId>>> = (0..n)
        .map(|k| algo::crba_derivative(chain, k).map(|dm| flat(&matrix_ids(&dm))))
        .collect();
    let carried = algo::coriolis_matrix(chain, qd).map(|c| matrix_ids(&c));
    let qd = ids(qd);
    let mut g = graph.borrow_mut();
    let mass = flat(mass);
    let traced: Vec<Vec<NodeId>> = (0..n)
        .map(|k| g.derivative(&mass, joint_index(k)))
        .collect();
    let by_algorithm: Vec<Vec<NodeId>> = analytic
        .into_iter()
        .zip(&traced)
        .map(|(a, t)| a.unwrap_or_else(|| t.clone()))
        .collect();
    let mut sums = Vec::with_capacity(4);
    for dm in [&traced, &by_algorithm] {
        let christoffel = christoffel_symbols(&mut g, dm, half);
        for c in coriolis_sums(&mut g, dm, &christoffel, &qd, half) {
            sums.push((christoffel.clone(), c));
        }
    }
    let mut sums = sums.into_iter();
    let Some(first) = sums.next() else {
        return (Vec::new(), Vec::new());
    };
    let by_sums = cheapest(&g, first, sums, |(_, c)| flat(c));
    let carried = carried.map(|c| (by_sums.0.clone(), c));
    cheapest(&g, by_sums, carried, |(_, c)| flat(c))
}

/// `Γ_ijk = ½(∂M_ij/∂q_k + ∂M_ik/∂q_j − ∂M_jk/∂q_i)` from `dm[k]` = `∂M/∂q_k` (rows first),
/// built from the ordered pair (j, k) so that hash-consing makes `Γ_ikj` the same node.
fn christoffel_symbols(g: &mut Graph, dm: &[Vec<NodeId>], half: NodeId) -> Christoffel {
    let n = dm.len();
    let d = |k: usize, i: usize, j: usize| dm[k][i * n + j];
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    (0..n)
                        .map(|k| {
                            let (j, k) = (j.min(k), j.max(k));
                            let s = g.add(d(k, i, j), d(j, i, k));
                            let s = g.sub(s, d(i, j, k));
                            g.mul(half, s)
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// `C_ij = Σ_k Γ_ijk q̇_k` summed two ways: over the symbols, and as `½(Ṁ_ij + P_ij − P_ji)`
/// with `Ṁ_ij = Σ_k ∂M_ij/∂q_k q̇_k` and `P_ij = Σ_k ∂M_ik/∂q_j q̇_k`.
fn coriolis_sums(
    g: &mut Graph,
    dm: &[Vec<NodeId>],
    christoffel: &[Vec<Vec<NodeId>>],
    qd: &[NodeId],
    half: NodeId,
) -> [Vec<Vec<NodeId>>; 2] {
    let n = dm.len();
    let d = |k: usize, i: usize, j: usize| dm[k][i * n + j];
    let contract = |g: &mut Graph, term: &dyn Fn(usize) -> NodeId| {
        let mut sum = g.num(Number::ZERO);
        for (k, &qd_k) in qd.iter().enumerate() {
            let t = g.mul(term(k), qd_k);
            sum = g.add(sum, t);
        }
        sum
    };
    let by_symbols: Vec<Vec<NodeId>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| contract(g, &|k| christoffel[i][j][k]))
                .collect()
        })
        .collect();
    let mut by_derivatives = vec![vec![half; n]; n];
    #[allow(clippy::needless_range_loop)] // fills C_ij and C_ji together
    for i in 0..n {
        let m_dot = contract(g, &|k| d(k, i, i));
        by_derivatives[i][i] = g.mul(half, m_dot);
        for j in i + 1..n {
            let m_dot = contract(g, &|k| d(k, i, j));
            let p_ij = contract(g, &|k| d(j, i, k));
            let p_ji = contract(g, &|k| d(i, j, k));
            let skew = g.sub(p_ij, p_ji);
            let upper = g.add(m_dot, skew);
            let lower = g.sub(m_dot, skew);
            by_derivatives[i][j] = g.mul(half, upper);
            by_derivatives[j][i] = g.mul(half, lower);
        }
    }
    [by_symbols, by_derivatives]
}
