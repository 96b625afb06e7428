//! The kinematics traced (`algo::kinematics`): the pose of every link frame and of the hand,
//! the hand's Jacobians in the base and hand frames, their acceleration bias `J̇ q̇`, and the
//! joint torques `T = Jᵀ F` (eq. 6.64) of a wrench at the hand, in either frame.
//!
//! Traced after the dynamics, so that the dynamics' node ids (and their generated code) are
//! those of a robot without kinematics.

use super::cost::{ids, matrix_ids};
use super::expr::Expr;
use super::tracer::Tracer;
use crate::algo::{self, Frame, Jacobian};
use crate::model::Robot;
use crate::symbolic::{NodeId, Var};

/// The kinematic outputs, as node ids.
#[derive(Clone, Debug, Default)]
pub struct KinematicEquations {
    /// The hand frame's rows `[R | p]`, 3 × 4, in the base frame.
    pub hand_pose: Vec<Vec<NodeId>>,
    /// Each link frame's rows `[R | p]` in the base frame.
    pub link_poses: Vec<Vec<Vec<NodeId>>>,
    /// The hand's geometric Jacobian in the base frame, 6 × n.
    pub jacobian_in_base: Vec<Vec<NodeId>>,
    /// The book's ᴴJ, 6 × n.
    pub jacobian_in_hand: Vec<Vec<NodeId>>,
    /// `J̇ q̇` in the base frame.
    pub bias_in_base: Vec<NodeId>,
    /// The same acceleration in the hand's axes.
    pub bias_in_hand: Vec<NodeId>,
    /// `ᴴJᵀ F` for a wrench in the hand frame.
    pub torques_for_hand_wrench: Vec<NodeId>,
    /// `Jᵀ F` for a wrench in base axes, about the hand's origin.
    pub torques_for_base_wrench: Vec<NodeId>,
}

/// Traces the kinematics of `robot`; `qd` are the joint velocities' leaves.
pub(super) fn kinematics(
    tracer: &mut Tracer<'_>,
    robot: &Robot,
    qd: &[Expr<'_>],
) -> KinematicEquations {
    let k = algo::kinematics(tracer, robot);
    let in_base = algo::jacobian_in_base(&k);
    let in_hand = algo::jacobian_in_hand(&k);
    let bias_in_base = algo::acceleration_bias_in_base(&k, &in_base, qd);
    let bias_in_hand = algo::in_hand_axes(&k, &bias_in_base);
    let wrench: [Expr; 6] = std::array::from_fn(|i| tracer.var(Var::Wrench(i as u16)));
    KinematicEquations {
        hand_pose: rows(&k.hand),
        link_poses: k.links.iter().map(rows).collect(),
        torques_for_hand_wrench: ids(&algo::joint_torques(&in_hand, &wrench)),
        torques_for_base_wrench: ids(&algo::joint_torques(&in_base, &wrench)),
        jacobian_in_base: jacobian_ids(&in_base),
        jacobian_in_hand: jacobian_ids(&in_hand),
        bias_in_base: ids(&bias_in_base),
        bias_in_hand: ids(&bias_in_hand),
    }
}

fn rows(frame: &Frame<Expr<'_>>) -> Vec<Vec<NodeId>> {
    matrix_ids(&frame.rows().map(Vec::from))
}

fn jacobian_ids(j: &Jacobian<Expr<'_>>) -> Vec<Vec<NodeId>> {
    matrix_ids(j)
}
