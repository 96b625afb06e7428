//! The tips' kinematics traced (`algo::tip_kinematics`, the hand's algorithms with each tip for
//! the hand): every tip's pose, Jacobians in the base and tip frames, acceleration bias `J̇ q̇`
//! in both, and the joint torques `Σ_t J_tᵀ F_t` of a wrench at each tip, in either frame.
//!
//! Traced into the shared graph after every other output, so that the others keep their
//! nodes; the graph's interning makes the link frames the tips share the same nodes.

use super::cost::{ids, matrix_ids};
use super::expr::Expr;
use super::joints::JointTerms;
use super::mimic::Reduction;
use super::tracer::Tracer;
use super::Equations;
use super::Shape;
use crate::algo;
use crate::method::{Family, Method};
use crate::model::Robot;
use crate::symbolic::{Graph, NodeId, Var};
use std::cell::RefCell;

/// The tips' outputs, as node ids, one entry per tip.
#[derive(Clone, Debug, Default)]
pub struct TipEquations {
    /// The tips' names, in order.
    pub names: Vec<String>,
    /// Each tip's rows `[R | p]`, 3 × 4, in the base frame.
    pub poses: Vec<Vec<Vec<NodeId>>>,
    /// Each tip's Jacobian in the base frame, 6 × n.
    pub jacobians_in_base: Vec<Vec<Vec<NodeId>>>,
    /// Each tip's Jacobian in its own frame, 6 × n.
    pub jacobians_in_tip: Vec<Vec<Vec<NodeId>>>,
    /// Each tip's `J̇ q̇` in the base frame, a row per tip.
    pub biases_in_base: Vec<Vec<NodeId>>,
    /// The same in each tip's axes.
    pub biases_in_tip: Vec<Vec<NodeId>>,
    /// `Σ_t J_tᵀ F_t`, each wrench in its tip's frame ([`Var::TipWrench`]).
    pub torques_for_tip_wrenches: Vec<NodeId>,
    /// `Σ_t J_tᵀ F_t`, each wrench in base axes.
    pub torques_for_base_wrenches: Vec<NodeId>,
}

impl TipEquations {
    /// No tips: the equations of a robot whose tips were not traced.
    pub const NONE: TipEquations = TipEquations {
        names: Vec::new(),
        poses: Vec::new(),
        jacobians_in_base: Vec::new(),
        jacobians_in_tip: Vec::new(),
        biases_in_base: Vec::new(),
        biases_in_tip: Vec::new(),
        torques_for_tip_wrenches: Vec::new(),
        torques_for_base_wrenches: Vec::new(),
    };

    /// The result of one of the tips' methods (which [`Method::shape`] sends here).
    pub(super) fn shape(&self, method: Method) -> Shape<'_> {
        match method {
            Method::TipPoses => Shape::Stack(&self.poses),
            Method::TipJacobiansInBase => Shape::Stack(&self.jacobians_in_base),
            Method::TipJacobiansInTip => Shape::Stack(&self.jacobians_in_tip),
            Method::TipAccelerationBiasesInBase => Shape::Matrix(&self.biases_in_base),
            Method::TipAccelerationBiasesInTip => Shape::Matrix(&self.biases_in_tip),
            Method::JointTorquesForTipWrenchesInBase => {
                Shape::Vector(&self.torques_for_base_wrenches)
            }
            // `JointTorquesForTipWrenches`, the last of them.
            _ => Shape::Vector(&self.torques_for_tip_wrenches),
        }
    }
}

impl Equations {
    /// Traces the kinematics of every tip of `robot` ([`Robot::tip_frames`]).
    pub fn add_tips(&mut self, robot: &Robot) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let fields = self.fields.clone();
        let mut tracer = Tracer::new(&graph, &fields, robot);
        let zero = tracer.num(crate::symbolic::Number::ZERO);
        let qd = JointTerms::new(&tracer, robot, zero).qd;
        let tips = robot.tip_frames();
        let mut out = TipEquations::default();
        let (mut in_tip_sum, mut in_base_sum) = (Vec::new(), Vec::new());
        for (t, tip) in tips.iter().enumerate() {
            let k = algo::tip_kinematics(&mut tracer, robot, tip);
            let in_base = algo::jacobian_in_base(&k);
            let in_tip = algo::jacobian_in_hand(&k);
            let bias_in_base = algo::acceleration_bias_in_base(&k, &in_base, &qd);
            let bias_in_tip = algo::in_hand_axes(&k, &bias_in_base);
            let wrench: [Expr; 6] = std::array::from_fn(|c| {
                let index = u16::try_from(6 * t + c).unwrap_or(u16::MAX);
                tracer.var(Var::TipWrench(index))
            });
            add_into(&mut in_tip_sum, algo::joint_torques(&in_tip, &wrench));
            add_into(&mut in_base_sum, algo::joint_torques(&in_base, &wrench));
            out.names.push(tip.name.clone());
            out.poses.push(matrix_ids(&k.hand.rows().map(Vec::from)));
            out.jacobians_in_base.push(matrix_ids(&in_base));
            out.jacobians_in_tip.push(matrix_ids(&in_tip));
            out.biases_in_base.push(ids(&bias_in_base));
            out.biases_in_tip.push(ids(&bias_in_tip));
        }
        // A robot has a tip (a leaf, else a named link that moves); none would give zeros.
        let none = || vec![zero; robot.dof()];
        let sum = |s: Vec<Expr>| ids(&if s.is_empty() { none() } else { s });
        out.torques_for_tip_wrenches = sum(in_tip_sum);
        out.torques_for_base_wrenches = sum(in_base_sum);
        if robot.has_mimics() {
            // In the coordinates, as every other output ([`super::mimic`]).
            let offsets = tracer.angle_offsets();
            let reduction = Reduction::new(&graph, &tracer, robot, &offsets);
            out = reduced(&reduction, &mut graph.borrow_mut(), &out);
        }
        drop(tracer);
        self.graph = graph.into_inner();
        self.tips = Some(out);
        self.families = self.families.with(Family::Tips);
    }
}

/// `sum += terms`, element by element (`sum` empty: the terms).
fn add_into<'g>(sum: &mut Vec<Expr<'g>>, terms: Vec<Expr<'g>>) {
    if sum.is_empty() {
        *sum = terms;
    } else {
        for (s, t) in sum.iter_mut().zip(terms) {
            *s = *s + t;
        }
    }
}

/// Every tip's kinematics in the coordinates, as the hand's ([`Reduction::kinematics`]).
fn reduced(r: &Reduction, g: &mut Graph, t: &TipEquations) -> TipEquations {
    let poses = |g: &mut Graph, rows: &[Vec<NodeId>]| -> Vec<Vec<NodeId>> {
        rows.iter().map(|row| r.substitute(g, row)).collect()
    };
    let substituted = |g: &mut Graph, vs: &[Vec<NodeId>]| -> Vec<Vec<NodeId>> {
        vs.iter().map(|v| r.substitute(g, v)).collect()
    };
    TipEquations {
        names: t.names.clone(),
        poses: t.poses.iter().map(|p| poses(g, p)).collect(),
        jacobians_in_base: t.jacobians_in_base.iter().map(|j| r.rows(g, j)).collect(),
        jacobians_in_tip: t.jacobians_in_tip.iter().map(|j| r.rows(g, j)).collect(),
        biases_in_base: substituted(g, &t.biases_in_base),
        biases_in_tip: substituted(g, &t.biases_in_tip),
        torques_for_tip_wrenches: r.vector(g, &t.torques_for_tip_wrenches),
        torques_for_base_wrenches: r.vector(g, &t.torques_for_base_wrenches),
    }
}
