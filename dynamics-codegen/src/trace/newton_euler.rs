//! The outputs of recursive Newton-Euler ([`algo::rnea`]): `τ = M q̈ + C q̇ + g` (the book's
//! T_i, eq. 6.46), `C q̇` (no gravity, `q̈ = 0`) and the bias `C q̇ + g` (`q̈ = 0`), with the
//! actuator inertia's `I q̈_i` and the springs' torques.
//!
//! Each is traced joint by joint and, where the robot has runs of parallel joints, with their
//! rates turned through the sums of the run's angles ([`Chain::summing_angles`]); the cheaper
//! trace is kept, output by output.

use super::cost::{cheapest, ids};
use super::expr::Expr;
use super::joints::JointTerms;
use crate::algo::{self, Chain, V3};
use crate::symbolic::{Graph, NodeId};
use std::cell::RefCell;

/// `C q̇`, `C q̇ + g` and `τ`.
pub(super) struct NewtonEuler {
    pub coriolis_torques: Vec<NodeId>,
    pub bias: Vec<NodeId>,
    pub tau: Vec<NodeId>,
}

/// The Newton-Euler outputs of `chain`, each the cheaper of its candidates.
pub(super) fn newton_euler<'g>(
    graph: &'g RefCell<Graph>,
    chain: &Chain<Expr<'g>>,
    gravity: V3<Expr<'g>>,
    joints: &JointTerms<'g>,
) -> NewtonEuler {
    let summed = chain.clone().summing_angles(true);
    let rnea = |qdd: &[Expr<'g>], gravity| {
        let joint_by_joint = algo::rnea(chain, &joints.qd, qdd, gravity);
        let by_sums = summed
            .has_runs()
            .then(|| algo::rnea(&summed, &joints.qd, qdd, gravity));
        cheapest(&graph.borrow(), joint_by_joint, by_sums, |t| ids(t))
    };
    let zeros = joints.zeros();
    let coriolis_torques = rnea(&zeros, V3::zero(joints.zero));
    let bias = joints.with_springs(rnea(&zeros, gravity));
    let tau: Vec<Expr> = rnea(&joints.qdd, gravity)
        .into_iter()
        .enumerate()
        .map(|(i, x)| x + joints.actuator[i] * joints.qdd[i] + joints.spring_torque(i))
        .collect();
    NewtonEuler {
        coriolis_torques: ids(&coriolis_torques),
        bias: ids(&bias),
        tau: ids(&tau),
    }
}
