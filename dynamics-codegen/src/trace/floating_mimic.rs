//! Mimic joints on a floating base: the outputs in the robot's coordinates, the base's six then
//! every joint but the mimic ones, with the map `S̃ = diag(1₆, S)` ([`super::mimic`]: joint m
//! follows `q_m = k q_j + o`, `v_m = k v_j`, the base's twist its own):
//!
//! ```text
//! M' = S̃ᵀ M S̃,  h' = S̃ᵀ h,  τ' = S̃ᵀ τ,  g' = S̃ᵀ g,  τ_f' = S̃ᵀ τ_f(S̃ v),  J' = J S̃,
//! a' = M'⁻¹ (τ' − h' − τ_f')
//! ```
//!
//! each traced on every joint with its own leaves, as for a robot without mimics, then the
//! joints' leaves replaced by the coordinates' and the rows (and columns) summed with their
//! factors k. Pinocchio 4's `JointModelMimic` on a free flyer is the same reduced system.
//! The forward dynamics solve with the LDLᵀ of `M'`: the articulated-body route
//! ([`crate::algo::floating_aba`]) runs on the joints and has no reduced form as written.

use super::mimic::Reduction;
use super::tracer::Tracer;
use crate::model::{JointKind, Robot};
use crate::symbolic::{Graph, NodeId};
use std::cell::RefCell;

/// The floating equations traced on every joint, `6 + joints` long, or in the coordinates.
pub(super) struct JointOutputs {
    pub mass: Vec<Vec<NodeId>>,
    pub bias: Vec<NodeId>,
    pub tau: Vec<NodeId>,
    pub gravity: Vec<NodeId>,
    pub friction: Vec<NodeId>,
    pub kinds: Vec<JointKind>,
    pub angle_offsets: Vec<Option<NodeId>>,
}

/// `out` in the coordinates of `robot` where it has mimic joints, else as it is (every node
/// of such a robot stays); `tracer` the one that traced them.
pub(super) fn in_coordinates(
    graph: &RefCell<Graph>,
    tracer: &Tracer<'_>,
    robot: &Robot,
    out: JointOutputs,
) -> JointOutputs {
    if !robot.has_mimics() {
        return out;
    }
    let r = Reduction::shifted(graph, tracer, robot, &out.angle_offsets, tracer.shift());
    let g = &mut graph.borrow_mut();
    JointOutputs {
        mass: r.matrix(g, &out.mass),
        bias: r.vector(g, &out.bias),
        tau: r.vector(g, &out.tau),
        gravity: r.vector(g, &out.gravity),
        friction: r.vector(g, &out.friction),
        kinds: r.of_coordinates(&out.kinds),
        angle_offsets: r.of_coordinates(&out.angle_offsets),
    }
}
