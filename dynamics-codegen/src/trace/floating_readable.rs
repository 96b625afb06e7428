//! The floating-base equations as `dynamics inspect --floating` prints them: `M`, `h`, `τ` and
//! `g` of [`super::derive_floating`], traced with gravity in base axes, `g_b = Rᵀ g`, as three
//! leaves (parameters named [`BASE_GRAVITY`]) in place of the quaternion's polynomial, and
//! `g_b` itself from the quaternion `[qx, qy, qz, qw]`. The same equations: the quaternion
//! enters them through `g_b` alone (`algo::floating`), so each component of `g_b` is printed
//! once, in its own equation, rather than its terms multiplied into every term that reads it.

use super::expr::Expr;
use super::floating::{floating_base, BASE_COORDINATES};
use super::tracer::{joint_index, Tracer};
use super::{Equations, KinematicEquations};
use crate::algo::{self, quaternion_rotation, RobotScalars, V3};
use crate::method::FamilySet;
use crate::model::{FreeFlyer, JointKind, Robot};
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The names of `g_b`'s leaves among the equations' fields: not identifiers, so never a
/// struct field's.
pub const BASE_GRAVITY: [&str; 3] = ["g_b.x", "g_b.y", "g_b.z"];

/// The floating-base equations with `g_b` as leaves, and `g_b` from the quaternion.
pub struct FloatingReadable {
    /// `M`, `h`, `τ`, `g` over the leaves of `g_b` (`fields` ends with [`BASE_GRAVITY`]).
    pub eq: Equations,
    /// `g_b = Rᵀ g`, `R` the quaternion's matrix ([`algo::quaternion_rotation`], not
    /// normalised), `g` the world's gravity.
    pub base_gravity: [NodeId; 3],
}

/// Traces `M`, `h`, `τ` and `g` of `robot` on the free flyer `flyer` over `g_b`'s leaves. The
/// front end has checked the robot; it has no mimic joints.
#[must_use]
pub fn derive_floating_readable(robot: &Robot, flyer: &FreeFlyer) -> FloatingReadable {
    let mut names = std::collections::BTreeSet::new();
    for v in robot.values().chain(flyer.values()) {
        v.collect_fields(&mut names);
    }
    let mut fields: Vec<String> = names.into_iter().collect();
    let first = fields.len();
    fields.extend(BASE_GRAVITY.map(str::to_owned));
    let graph = RefCell::new(Graph::new());
    let mut tracer = Tracer::new(&graph, &fields, robot).shifted(BASE_COORDINATES);
    let chain = tracer.chain(robot);
    let base = floating_base(&tracer, robot, flyer);
    let nv = robot.dof() + BASE_COORDINATES;
    let vars = |kind: fn(u16) -> Var| -> Vec<Expr> {
        (0..nv).map(|i| tracer.var(kind(joint_index(i)))).collect()
    };
    let (v, a) = (vars(Var::Qd), vars(Var::Qdd));
    let (zero, one) = (tracer.num(Number::ZERO), tracer.num(Number::ONE));
    // R = 1: gravity in world axes is then gravity in base axes, the leaves.
    let identity = [zero, zero, zero, one];
    let leaf = |k: usize| tracer.var(Var::Param(joint_index(first + k)));
    let g_b = V3::new(leaf(0), leaf(1), leaf(2));
    let zeros = vec![zero; nv];
    let ids = |x: Vec<Expr>| x.into_iter().map(Expr::id).collect::<Vec<_>>();
    let mass: Vec<_> = algo::floating_crba(&chain, &base)
        .into_iter()
        .map(ids)
        .collect();
    let bias = ids(algo::floating_rnea(
        &chain, &base, identity, &v, &zeros, g_b,
    ));
    let tau = ids(algo::floating_rnea(&chain, &base, identity, &v, &a, g_b));
    let gravity = ids(algo::floating_gravity(&chain, &base, identity, g_b));
    let quaternion = [2, 3, 4, 5].map(|k| tracer.var(Var::Q(k)));
    let g = flyer.gravity.each_ref().map(|x| tracer.value(x));
    let turned = quaternion_rotation(quaternion).tr_mul_vec(V3::new(g[0], g[1], g[2]));
    let base_gravity = [turned.x.id(), turned.y.id(), turned.z.id()];
    let kinds = [JointKind::Prismatic; BASE_COORDINATES]
        .into_iter()
        .chain(robot.joints.iter().map(|j| j.kind))
        .collect();
    let angle_offsets = tracer.angle_offsets();
    let nothing = zero.id();
    let forward = super::forward::forward(&graph, &mass, &bias, &vec![nothing; nv], true);
    let eq = Equations {
        graph: graph.into_inner(),
        dof: nv,
        links: robot.dof(),
        fields,
        kinds,
        angle_offsets,
        mass,
        christoffel: Vec::new(),
        coriolis: Vec::new(),
        coriolis_torques: Vec::new(),
        gravity,
        bias,
        tau,
        friction: Vec::new(),
        kinetic_energy: nothing,
        potential_energy: nothing,
        kinematics: KinematicEquations::default(),
        forward,
        families: FamilySet::floating(),
        derivatives: None,
        regressor: None,
        base_parameters: None,
        simplified: None,
        tips: None,
    };
    FloatingReadable { eq, base_gravity }
}
