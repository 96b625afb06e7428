//! The kinetic energy `K` (eq. 6.39) and the potential energy `P` (eq. 6.40) of the links
//! ([`algo::kinetic_energy`], [`algo::potential_energy`]), plus the actuators'
//! `½ I_i(act) q̇_i²` and the springs' `½ k_i (q_i − rest_i)²`.

use super::expr::Expr;
use super::joints::JointTerms;
use crate::algo::{self, Chain, V3};
use crate::symbolic::NodeId;

/// The kinetic and the potential energy.
pub(super) fn energies<'g>(
    chain: &Chain<Expr<'g>>,
    gravity: V3<Expr<'g>>,
    joints: &JointTerms<'g>,
    half: Expr<'g>,
) -> (NodeId, NodeId) {
    let (qd, actuator) = (&joints.qd, &joints.actuator);
    let mut kinetic = algo::kinetic_energy(chain, qd, joints.zero);
    for i in 0..qd.len() {
        kinetic = kinetic + half * actuator[i] * qd[i] * qd[i];
    }
    let mut potential = algo::potential_energy(chain, gravity);
    for (i, s) in joints.springs.iter().enumerate() {
        if let Some((k, rest)) = s {
            let dq = joints.q[i] - *rest;
            potential = potential + half * *k * dq * dq;
        }
    }
    (kinetic.id(), potential.id())
}
