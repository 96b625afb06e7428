//! Joint friction, outside the rigid-body algorithms: per joint
//! `τ_f,i = f_v q̇_i + f_c sign(q̇_i) + f_0`, with `sign(0) = 0` (no Coulomb torque at rest),
//! or `f_c tanh(q̇_i / ε)` in place of the sign where a smoothing velocity ε is given. Zero for
//! a joint without friction, so that a robot without any adds no node to the graph.

use super::expr::Expr;
use super::tracer::Tracer;
use crate::algo::{RobotScalars, Scalar};
use crate::model::Robot;
use crate::symbolic::NodeId;

/// The friction torque of each joint of `robot`, `qd` its joints' rates (a floating base's
/// after the base's six).
pub(super) fn friction_torques<'g>(
    t: &Tracer<'g>,
    robot: &Robot,
    qd: &[Expr<'g>],
    zero: Expr<'g>,
) -> Vec<NodeId> {
    robot
        .joints
        .iter()
        .zip(qd)
        .map(|(joint, &qd)| {
            let Some(f) = &joint.link.friction else {
                return zero.id();
            };
            let coulomb = t.value(&f.coulomb);
            let direction = match &f.smoothing {
                None => t.sign(qd),
                Some(eps) => {
                    let scaled = qd * t.reciprocal(&t.value(eps));
                    t.tanh(scaled)
                }
            };
            // Coulomb's function is only built where its coefficient is not zero.
            let coulomb = if coulomb.is_zero() {
                coulomb
            } else {
                coulomb * direction
            };
            (t.value(&f.viscous) * qd + coulomb + t.value(&f.offset)).id()
        })
        .collect()
}
