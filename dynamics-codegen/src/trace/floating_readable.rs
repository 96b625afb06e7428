//! The floating-base equations as `dynamics inspect --floating` prints them: `M`, `h`, `τ` and
//! `g` of [`super::derive_floating`], traced with gravity in base axes, `g_b = Rᵀ g`, as three
//! leaves (parameters named [`super::BASE_GRAVITY`]) in place of the quaternion's polynomial, and
//! `g_b` itself from the quaternion `[qx, qy, qz, qw]`. The same equations: the quaternion
//! enters them through `g_b` alone (`algo::floating`), so each component of `g_b` is printed
//! once, in its own equation, rather than its terms multiplied into every term that reads it.

use super::floating::{base_quaternion, trace_floating, world_gravity, Gravity, BASE_COORDINATES};
use super::tracer::Tracer;
use super::Equations;
use crate::algo::quaternion_rotation;
use crate::model::{FreeFlyer, Robot};
use crate::symbolic::NodeId;
use std::cell::RefCell;

/// The floating-base equations with `g_b` as leaves, and `g_b` from the quaternion.
pub struct FloatingReadable {
    /// `M`, `h`, `τ`, `g` over the leaves of `g_b` (`fields` ends with [`super::BASE_GRAVITY`]).
    pub eq: Equations,
    /// `g_b = Rᵀ g`, `R` the quaternion's matrix ([`quaternion_rotation`], not normalised), `g`
    /// the world's gravity.
    pub base_gravity: [NodeId; 3],
}

/// Traces `M`, `h`, `τ` and `g` of `robot` on the free flyer `flyer` over `g_b`'s leaves (the
/// joints' friction and actuator inertia included, as the derive's), and `g_b` in the same
/// graph, in the coordinates of a robot with mimic joints. The front end has checked the robot.
#[must_use]
pub fn derive_floating_readable(robot: &Robot, flyer: &FreeFlyer) -> FloatingReadable {
    let mut eq = trace_floating(robot, flyer, Gravity::BaseLeaves);
    let graph = RefCell::new(std::mem::take(&mut eq.graph));
    let tracer = Tracer::new(&graph, &eq.fields, robot).shifted(BASE_COORDINATES);
    let turned =
        quaternion_rotation(base_quaternion(&tracer)).tr_mul_vec(world_gravity(&tracer, flyer));
    let base_gravity = [turned.x.id(), turned.y.id(), turned.z.id()];
    drop(tracer);
    eq.graph = graph.into_inner();
    FloatingReadable { eq, base_gravity }
}
