//! The equations of a tree on a free-flying base ([`algo::floating_rnea`],
//! [`algo::floating_crba`]): `M`, the bias `h = C v + g`, `τ = M a + h + τ_f` and the
//! generalized gravity `g`, each `6 + n` long, and the forward dynamics
//! `a = M⁻¹ (τ − h − τ_f)` and `M⁻¹` through the LDLᵀ of `M` factored from the tips, in one
//! graph. The joints' actuator inertia (Pinocchio's armature) is on `M`'s diagonal; their
//! friction `τ_f` (`f_v q̇ + f_c sign(q̇) + f_0`, zero in the base's rows) is in `τ` and the
//! forward dynamics, not in `h` (as a fixed base's `bias_torques`, and Pinocchio's
//! `nonLinearEffects`).
//!
//! The coordinates are numbered as the velocity's: the base's six (`0..6`), then joint i at
//! `6 + i` ([`Var::Q`], [`Var::SinQ`], [`Var::Qd`], [`Var::Qdd`] alike). The configuration
//! `[x, y, z, qx, qy, qz, qw, q_1 …]` is read without its first entry, which nothing reads
//! (the base position): `Var::Q(k)` is its entry `k + 1`, so the quaternion is `Q(2..6)` and
//! joint i's angle `Q(6 + i)`. The chain is traced as given, not regrouped: a floating base's
//! rows see every link parameter, so no parameter may be moved onto another.

use super::cost::operations;
use super::expr::Expr;
use super::floating_mimic::{in_coordinates, JointOutputs};
use super::forward::ForwardEquations;
use super::tracer::{joint_index, Tracer};
use super::{Equations, KinematicEquations};
use crate::algo::{self, FloatingBase, Inertial, Mat3, RobotScalars, V3};
use crate::method::FamilySet;
use crate::model::{FreeFlyer, JointKind, Robot};
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The coordinates of the base: the velocity's first six.
pub const BASE_COORDINATES: usize = 6;

/// Traces the floating-base equations of `robot` on the free flyer `flyer`, in its coordinates
/// where it has mimic joints (`floating_mimic`). The front end has checked the robot.
#[must_use]
pub fn derive_floating(robot: &Robot, flyer: &FreeFlyer) -> Equations {
    trace_floating(robot, flyer, Gravity::World)
}

/// How the floating equations read gravity.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Gravity {
    /// The world's, turned into base axes by the quaternion: the derive's equations.
    World,
    /// In base axes, as three leaves named [`BASE_GRAVITY`] after the fields (`R = 1`): the
    /// same polynomials with `g_b`'s terms written once, for the readable equations.
    BaseLeaves,
}

/// The names of `g_b`'s leaves among the readable equations' fields: not identifiers, so never
/// a struct field's.
pub const BASE_GRAVITY: [&str; 3] = ["g_b.x", "g_b.y", "g_b.z"];

/// [`derive_floating`], gravity read as `gravity` says.
pub(super) fn trace_floating(robot: &Robot, flyer: &FreeFlyer, gravity: Gravity) -> Equations {
    let mut fields = floating_fields(robot, flyer);
    let first = fields.len();
    if gravity == Gravity::BaseLeaves {
        fields.extend(BASE_GRAVITY.map(str::to_owned));
    }
    let graph = RefCell::new(Graph::new());
    let mut tracer = Tracer::new(&graph, &fields, robot).shifted(BASE_COORDINATES);
    let zero = tracer.num(Number::ZERO);
    let chain = tracer.chain(robot);
    let base = floating_base(&tracer, robot, flyer);
    let nv = robot.dof() + BASE_COORDINATES;
    let (v, a) = (
        coordinates(&tracer, nv, Var::Qd),
        coordinates(&tracer, nv, Var::Qdd),
    );
    let readable = gravity == Gravity::BaseLeaves;
    let (quaternion, gravity) = match gravity {
        Gravity::World => (base_quaternion(&tracer), world_gravity(&tracer, flyer)),
        Gravity::BaseLeaves => {
            let one = tracer.num(Number::ONE);
            let leaf = |k: usize| tracer.var(Var::Param(joint_index(first + k)));
            ([zero, zero, zero, one], V3::new(leaf(0), leaf(1), leaf(2)))
        }
    };
    let zeros = vec![zero; nv];
    let ids = |x: Vec<Expr>| x.into_iter().map(Expr::id).collect::<Vec<_>>();
    let mut mass = algo::floating_crba(&chain, &base);
    let bias = ids(algo::floating_rnea(
        &chain, &base, quaternion, &v, &zeros, gravity,
    ));
    let mut tau = algo::floating_rnea(&chain, &base, quaternion, &v, &a, gravity);
    let gravity = ids(algo::floating_gravity(&chain, &base, quaternion, gravity));
    let friction = joint_terms(&tracer, robot, (&graph, &v, &a), &mut mass, &mut tau);
    let kinds = [JointKind::Prismatic; BASE_COORDINATES]
        .into_iter()
        .chain(robot.joints.iter().map(|j| j.kind))
        .collect();
    let joints = JointOutputs {
        mass: mass.into_iter().map(ids).collect(),
        bias,
        tau: ids(tau),
        gravity,
        friction,
        kinds,
        angle_offsets: tracer.angle_offsets(),
    };
    let out = in_coordinates(&graph, &tracer, robot, joints);
    // The base is the root of the tree: factored from the tips, each branch's joints reach
    // only their ancestors and the base's six, which keeps M's zeros (Featherstone's LTDL).
    let mut forward = super::forward::forward(&graph, &out.mass, &out.bias, &out.friction, true);
    // The articulated bodies run on the joints: a robot with mimic joints keeps the LDLᵀ.
    if !readable && !robot.has_mimics() {
        let tree = (&chain, &base);
        let aba = articulated(
            &tracer,
            robot,
            flyer,
            tree,
            (quaternion, &v),
            (&graph, &out.friction),
        );
        keep_the_cheaper(&graph, &mut forward, &aba);
    }
    let (nothing, links) = (zero.id(), robot.dof());
    drop(tracer);
    floating_equations(graph.into_inner(), fields, out, (forward, links), nothing)
}

/// The equations of the floating outputs `out` and `forward` in `graph`, `links` bodies past
/// the base (`nothing`, zero, for the outputs a floating base does not have).
fn floating_equations(
    graph: Graph,
    fields: Vec<String>,
    out: JointOutputs,
    (forward, links): (ForwardEquations, usize),
    nothing: NodeId,
) -> Equations {
    let JointOutputs {
        mass,
        bias,
        tau,
        gravity,
        friction,
        kinds,
        angle_offsets,
    } = out;
    Equations {
        graph,
        dof: mass.len(),
        links,
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
        friction,
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
    }
}

/// The free flyer's body and frame 0's placement on it, as expressions.
pub(super) fn floating_base<'g>(
    tracer: &Tracer<'g>,
    robot: &Robot,
    flyer: &FreeFlyer,
) -> FloatingBase<Expr<'g>> {
    let v = |x| tracer.value(x);
    let link = flyer_inertial(tracer, flyer);
    let (r, t) = (&robot.base.rotation, &robot.base.translation);
    let rotation = Mat3 {
        m: std::array::from_fn(|i| std::array::from_fn(|j| v(&r[i][j]))),
    };
    FloatingBase::new(&link, rotation, V3::new(v(&t[0]), v(&t[1]), v(&t[2])))
}

/// The free flyer's mass, centre of mass and inertia, as expressions.
pub(super) fn flyer_inertial<'g>(tracer: &Tracer<'g>, flyer: &FreeFlyer) -> Inertial<Expr<'g>> {
    let v = |x| tracer.value(x);
    let b = &flyer.body;
    Inertial {
        mass: v(&b.mass),
        com: V3::new(v(&b.com[0]), v(&b.com[1]), v(&b.com[2])),
        inertia: b.inertia.each_ref().map(v),
    }
}

/// The struct fields that the robot's and the free flyer's values name, sorted, once each.
pub(super) fn floating_fields(robot: &Robot, flyer: &FreeFlyer) -> Vec<String> {
    let mut names = std::collections::BTreeSet::new();
    for v in robot.values().chain(flyer.values()) {
        v.collect_fields(&mut names);
    }
    names.into_iter().collect()
}

/// The `nv` velocity coordinates of one kind (`Var::Qd`, `Var::Qdd`), the base's six first.
pub(super) fn coordinates<'g>(
    tracer: &Tracer<'g>,
    nv: usize,
    kind: fn(u16) -> Var,
) -> Vec<Expr<'g>> {
    (0..nv).map(|i| tracer.var(kind(joint_index(i)))).collect()
}

/// The base's unit quaternion `(qx, qy, qz, qw)`: the configuration's entries 3..7.
pub(super) fn base_quaternion<'g>(tracer: &Tracer<'g>) -> [Expr<'g>; 4] {
    [2, 3, 4, 5].map(|k| tracer.var(Var::Q(k)))
}

/// Gravity in world axes.
pub(super) fn world_gravity<'g>(tracer: &Tracer<'g>, flyer: &FreeFlyer) -> V3<Expr<'g>> {
    let g = flyer.gravity.each_ref().map(|x| tracer.value(x));
    V3::new(g[0], g[1], g[2])
}

/// The joints' own terms, on their rows: actuator inertia (Pinocchio's armature) on `mass`'s
/// diagonal and in `tau`, friction in `tau`; returns the friction torques, the base's six rows
/// zero, for the forward dynamics' right-hand side. Zero for a joint without them, which
/// folds: such a robot keeps every node it had.
fn joint_terms<'g>(
    tracer: &Tracer<'g>,
    robot: &Robot,
    (graph, v, a): (&'g RefCell<Graph>, &[Expr<'g>], &[Expr<'g>]),
    mass: &mut [Vec<Expr<'g>>],
    tau: &mut [Expr<'g>],
) -> Vec<NodeId> {
    let zero = tracer.num(Number::ZERO);
    let friction = super::friction::friction_torques(tracer, robot, &v[BASE_COORDINATES..], zero);
    for (i, joint) in robot.joints.iter().enumerate() {
        let k = BASE_COORDINATES + i;
        let armature = tracer.value(&joint.link.actuator_inertia);
        mass[k][k] = mass[k][k] + armature;
        tau[k] = tau[k] + armature * a[k] + Expr::new(graph, friction[i]);
    }
    [zero.id(); BASE_COORDINATES]
        .into_iter()
        .chain(friction)
        .collect()
}

/// The forward dynamics by the articulated-body algorithm ([`algo::floating_aba`]), for
/// `τ − τ_f` (leaves [`Var::Tau`] of `graph` less `friction`), with the joints' armature.
fn articulated<'g>(
    tracer: &Tracer<'g>,
    robot: &Robot,
    flyer: &FreeFlyer,
    (chain, base): (&algo::Chain<Expr<'g>>, &FloatingBase<Expr<'g>>),
    (quaternion, v): ([Expr<'g>; 4], &[Expr<'g>]),
    (graph, friction): (&'g RefCell<Graph>, &[NodeId]),
) -> algo::Articulated<Expr<'g>> {
    let armature = robot
        .joints
        .iter()
        .map(|j| tracer.value(&j.link.actuator_inertia));
    let armature: Vec<Expr> = armature.collect();
    let rhs = forces_less_friction(graph, friction);
    let gravity = world_gravity(tracer, flyer);
    algo::floating_aba(chain, base, quaternion, v, &rhs, &armature, gravity)
}

/// `τ − τ_f`, the forward dynamics' generalized forces (leaves [`Var::Tau`]) less friction.
fn forces_less_friction<'g>(graph: &'g RefCell<Graph>, friction: &[NodeId]) -> Vec<Expr<'g>> {
    let tau = |i: usize| {
        let id = graph
            .borrow_mut()
            .var(Var::Tau(u16::try_from(i).unwrap_or(u16::MAX)));
        Expr::new(graph, id)
    };
    let f = |i: usize| Expr::new(graph, friction[i]);
    (0..friction.len()).map(|i| tau(i) - f(i)).collect()
}

/// The forward dynamics by the articulated-body algorithm `aba` in place of M, h and the
/// LDLᵀ where it takes fewer operations, as `forward_dynamics` returns it (its pivots with
/// it; the factors and the `q̈` through them stay, for M⁻¹, the contacts and the
/// derivatives).
fn keep_the_cheaper(
    graph: &RefCell<Graph>,
    forward: &mut ForwardEquations,
    aba: &algo::Articulated<Expr>,
) {
    let qdd: Vec<NodeId> = aba.acceleration.iter().map(|e| e.id()).collect();
    let pivots: Vec<NodeId> = aba.pivots.iter().map(|e| e.id()).collect();
    let cost = |x: &[NodeId], p: &[NodeId]| {
        let outputs: Vec<NodeId> = x.iter().chain(p).copied().collect();
        operations(&graph.borrow(), &outputs)
    };
    if cost(&qdd, &pivots) < cost(&forward.returned.0, &forward.returned.1) {
        forward.returned = (qdd, pivots);
    }
}
