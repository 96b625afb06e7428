//! The first derivatives of a tree on a free-flying base (opt-in, `derivatives = true`), traced
//! on the graph of [`super::derive_floating`] as Pinocchio's `computeRNEADerivatives` and
//! `computeABADerivatives` define them on the free flyer.
//!
//! A derivative by `q` is along the tangent: column j is `d/dε f(integrate(q, ε e_j))`, the base
//! moved in its own frame (position `δp`, rotation `δω`), then the joints. The base pose enters
//! τ only through gravity in base axes, `g_b = Rᵀ g` (the position nowhere), which turns as
//! `R → R exp([δω]×)` turns it: `d g_b = g_b × δω = [g_b]× δω`. And τ reads `g_b` only where it
//! reads the base's `v̇`, in `a_b = v̇ + ω × v − g_b`, so `∂τ/∂g_b = −∂τ/∂v̇ = −M[:, 0..3]`:
//!
//! * `∂τ/∂q`: the position's three columns zero, the rotation's `−M[:, 0..3] [g_b]×` (products
//!   of M's first three columns, which the graph has), the joints' the forward derivatives of
//!   τ's graph by `q_j` with the quaternion held (its components are not coordinates);
//! * `∂τ/∂v`: by each entry of `v`, the base's twist and the joint rates alike;
//! * `∂a/∂x = −M⁻¹ ∂τ/∂x` at the forward dynamics' `a`, as on a fixed base, but for the
//!   rotation: `−M⁻¹ (−M[:, 0..3] [g_b]×)` is exactly `[g_b]×` in the base's three linear rows
//!   and zero elsewhere (turning the base turns gravity in its frame, which accelerates every
//!   body alike), so those columns are written as such, not solved; `∂a/∂τ = M⁻¹`;
//! * where the build computes tangents in lanes, the joints' columns and `∂τ/∂v` planned as a
//!   fixed base's ([`Graph::tangents`] from the first joint's index on), the rotation's columns
//!   added to each row's lane as unit vectors times the nodes above.
//!
//! The joints' friction and actuator inertia need nothing of their own: τ and M hold them, so
//! `∂τ/∂v` gains the viscous coefficients on the joints' diagonal (Coulomb's `sign` is flat,
//! `∂ sign/∂v = 0` away from 0), `∂τ/∂q` nothing, and the solves use M with the armature at
//! `a = M⁻¹ (τ − h − τ_f)`.
//!
//! The quaternion is taken to be unit: for one that is not, `R` is not a rotation (see
//! [`crate::algo::quaternion_rotation`]) and no tangent moves the base along a rotation.

use super::derivatives::{forward_derivatives, transpose, DerivativeEquations};
use super::floating::{base_quaternion, world_gravity, BASE_COORDINATES};
use super::lane_solve::{self, lane_term};
use super::tracer::{joint_index, Tracer};
use super::Equations;
use crate::algo;
use crate::method::Family;
use crate::model::{FreeFlyer, Robot};
use crate::symbolic::{Graph, NodeId, Number, Of, Tangents, Term, Wrt, BLOCK, QUARTER_BLOCK};
use std::cell::RefCell;

/// The base rotation's three coordinates of the tangent: `δω`, after the position's.
const ROTATION: usize = 3;

impl Equations {
    /// Traces the first derivatives of the floating equations of `robot` on the free flyer
    /// `flyer` ([`Equations::derivatives`]) into the graph, after every other output, so that
    /// those keep their nodes.
    pub fn add_floating_derivatives(&mut self, robot: &Robot, flyer: &FreeFlyer) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let g_b = base_gravity(&graph, &self.fields, robot, flyer);
        let turned = rotation_columns(&mut graph.borrow_mut(), &self.mass, g_b);
        let by_q = by_position(self, &graph, &turned);
        let by_v = by_velocity(self, &graph);
        // The joints' columns solved; the rotation's written exactly.
        let zero = graph.borrow_mut().num(Number::ZERO);
        let joints_only: Vec<Vec<NodeId>> = by_q
            .iter()
            .map(|row| {
                let mut row = row.clone();
                row[ROTATION..BASE_COORDINATES].fill(zero);
                row
            })
            .collect();
        let mut forward = forward_derivatives(self, &graph, &[joints_only, by_v.clone()]);
        let accelerated = accelerated_rows(&mut graph.borrow_mut(), g_b);
        for (row, columns) in forward[0].iter_mut().zip(&accelerated) {
            for (k, entry) in columns.iter().enumerate() {
                if let Some(entry) = entry {
                    row[ROTATION + k] = entry.node;
                }
            }
        }
        self.graph = graph.into_inner();
        let (inverse_lanes, forward_lanes) = lanes(self, &turned, &accelerated);
        self.derivatives = Some(DerivativeEquations {
            inverse: vec![by_q, by_v],
            inverse_lanes,
            qdd: self.forward.qdd.clone(),
            forward,
            forward_lanes,
        });
        self.families = self.families.with(Family::FloatingDerivatives);
    }
}

/// `g_b = Rᵀ g`, gravity in base axes, as the floating equations trace it.
fn base_gravity(
    graph: &RefCell<Graph>,
    fields: &[String],
    robot: &Robot,
    flyer: &FreeFlyer,
) -> [NodeId; 3] {
    let tracer = Tracer::new(graph, fields, robot).shifted(BASE_COORDINATES);
    let quaternion = base_quaternion(&tracer);
    let g_b = algo::quaternion_rotation(quaternion).tr_mul_vec(world_gravity(&tracer, flyer));
    [g_b.x.id(), g_b.y.id(), g_b.z.id()]
}

/// Per row i of τ, `∂τ_i/∂δω = −M[i, 0..3] [g_b]×`: `(M_i2 g_y − M_i1 g_z, M_i0 g_z − M_i2 g_x,
/// M_i1 g_x − M_i0 g_y)`.
fn rotation_columns(
    g: &mut Graph,
    mass: &[Vec<NodeId>],
    [x, y, z]: [NodeId; 3],
) -> Vec<[NodeId; 3]> {
    let mut cross = |a: NodeId, b: NodeId, c: NodeId, d: NodeId| {
        let (ab, cd) = (g.mul(a, b), g.mul(c, d));
        let minus = g.neg(cd);
        g.add(ab, minus)
    };
    mass.iter()
        .map(|row| {
            let [m0, m1, m2] = [row[0], row[1], row[2]];
            [
                cross(m2, y, m1, z),
                cross(m0, z, m2, x),
                cross(m1, x, m0, y),
            ]
        })
        .collect()
}

/// An entry of `∂a/∂δω`: `± g_b`'s component `of`, whose node is `node`.
#[derive(Clone, Copy)]
struct Entry {
    node: NodeId,
    of: NodeId,
    negated: bool,
}

/// `∂a/∂δω` in the base's three linear rows, `[g_b]×`, by column (`None` where zero):
/// `[[0, −g_z, g_y], [g_z, 0, −g_x], [−g_y, g_x, 0]]`.
fn accelerated_rows(g: &mut Graph, [x, y, z]: [NodeId; 3]) -> [[Option<Entry>; 3]; 3] {
    let mut entry = |of: NodeId, negated: bool| {
        let node = if negated { g.neg(of) } else { of };
        (!g.is_zero(node)).then_some(Entry { node, of, negated })
    };
    [
        [None, entry(z, true), entry(y, false)],
        [entry(z, false), None, entry(x, true)],
        [entry(y, true), entry(x, false), None],
    ]
}

/// `∂τ/∂q` along the tangent, rows first: zero for the base position, `turned` for its
/// rotation, the graph's derivative by each joint's angle.
fn by_position(eq: &Equations, graph: &RefCell<Graph>, turned: &[[NodeId; 3]]) -> Vec<Vec<NodeId>> {
    let mut g = graph.borrow_mut();
    let zero = g.num(Number::ZERO);
    let columns: Vec<Vec<NodeId>> = (0..eq.dof)
        .map(|j| match j {
            _ if j < ROTATION => vec![zero; eq.dof],
            _ if j < BASE_COORDINATES => turned.iter().map(|row| row[j - ROTATION]).collect(),
            _ => g.derivative_by(&eq.tau, Wrt::Position(joint_index(j))),
        })
        .collect();
    transpose(&columns)
}

/// `∂τ/∂v`, rows first: the graph's derivative by each entry of `v`.
fn by_velocity(eq: &Equations, graph: &RefCell<Graph>) -> Vec<Vec<NodeId>> {
    let mut g = graph.borrow_mut();
    let columns: Vec<Vec<NodeId>> = (0..eq.dof)
        .map(|j| g.derivative_by(&eq.tau, Wrt::Velocity(joint_index(j))))
        .collect();
    transpose(&columns)
}

/// The plans in lanes of `[∂τ/∂q, ∂τ/∂v]` and `[∂a/∂q, ∂a/∂v, ∂a/∂τ]` (as a fixed base's,
/// `derivatives.rs`), the rotation's columns added to the rows as unit vectors: `turned` to
/// `∂τ/∂q`'s, `accelerated` to `∂a/∂q`'s base linear rows.
fn lanes(
    eq: &mut Equations,
    turned: &[[NodeId; 3]],
    accelerated: &[[Option<Entry>; 3]; 3],
) -> (Vec<Option<Tangents>>, Vec<Option<Tangents>>) {
    let n = eq.dof;
    let first_joint = Wrt::Position(joint_index(BASE_COORDINATES));
    let joints = eq.graph.tangents(&eq.tau, first_joint, n);
    let by_v = eq.graph.tangents(&eq.tau, Wrt::Velocity(0), n);
    let graph = &eq.graph;
    let turned_terms = turned.iter().map(|row| {
        let nonzero = row.iter().enumerate().filter(|(_, &f)| !graph.is_zero(f));
        nonzero
            .map(|(k, &f)| lane_term(Of::Unit(unit(ROTATION + k)), vec![f], false))
            .collect()
    });
    let by_q = joints
        .clone()
        .map(|plan| with_columns(plan, turned_terms.collect()));
    let inverse = [by_q, by_v.clone()].map(|plan| {
        let mut plan = plan?;
        if plan.prefer_groups_of_four() {
            plan.group = QUARTER_BLOCK;
        }
        Some(plan)
    });
    let (graph, qdd, factors) = (&mut eq.graph, &eq.forward.qdd, &eq.forward.factors);
    let mut solved = [joints, by_v].map(|plan| {
        // In blocks of eight, as a fixed base's (the choice of four is ∂τ's alone).
        let eights = Tangents {
            group: BLOCK,
            ..plan?
        };
        let at_qdd = lane_solve::at_qdd(&eights, graph, qdd);
        Some(lane_solve::solve_negated(at_qdd, factors, graph))
    });
    let rows = accelerated.iter().map(|row| {
        let terms = row.iter().enumerate().filter_map(|(k, entry)| {
            let e = entry.as_ref()?;
            Some(lane_term(
                Of::Unit(unit(ROTATION + k)),
                vec![e.of],
                e.negated,
            ))
        });
        terms.collect()
    });
    solved[0] = solved[0]
        .take()
        .map(|plan| with_columns(plan, rows.collect()));
    let mut forward: Vec<Option<Tangents>> = solved.into();
    forward.push(Some(lane_solve::inverse(factors, graph)));
    (inverse.into(), forward)
}

/// `plan` with `rows[i]`'s terms added to output i's lane (the rows past `rows` unchanged).
fn with_columns(mut plan: Tangents, rows: Vec<Vec<Term>>) -> Tangents {
    for (i, extra) in rows.into_iter().enumerate() {
        if extra.is_empty() {
            continue;
        }
        let own = plan.outputs[i].map(|k| lane_term(Of::Lane(k), Vec::new(), false));
        let terms: Vec<Term> = own.into_iter().chain(extra).collect();
        plan.outputs[i] = lane_solve::write(&mut plan, terms);
    }
    plan
}

/// Direction `j` as a unit vector's index.
fn unit(j: usize) -> u16 {
    u16::try_from(j).unwrap_or(u16::MAX)
}
