//! The joint torque regressor of a tree on a free-flying base (opt-in, `regressor = true`), and
//! its base parameters (`base_parameters = true`): `τ = Σ_j Y_j(q, v, a) π_j` over the `n + 1`
//! bodies, the floating one first (`π_0` about the base origin, in base axes), then link j
//! about the origin of its link frame, each `π_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz,
//! Iyz, Izz]` (Pinocchio's `computeJointTorqueRegressor` on the free flyer, whose joint frames
//! are a URDF's link frames).
//!
//! τ is [`algo::floating_rnea`] traced on bodies made of ten placeholders each
//! ([`Var::Inertial`]): the floating body's, and each link's carried from its link frame to the
//! chain's joint frame as the fixed base's regressor carries it. The chain is not regrouped: on
//! a floating base every body's parameters reach the base's six rows, so none may be moved onto
//! another. τ is linear in the placeholders, so the column of `π_jk` is that trace with
//! `π_jk = 1` and every other placeholder 0, folded as it is rebuilt. The regressor has no
//! joint columns (actuator inertia, friction): the front end refuses it beside them.
//!
//! The base parameters are decided exactly as a fixed base's ([`super::base_parameters`]), on
//! the same columns traced with the description's constants as leaves. The quaternion's four
//! components are leaves of their own there, not a unit quaternion: gravity in base axes,
//! `g_b = Rᵀ g`, enters τ only beside the base's `v̇`, in `a_b = v̇ + ω × v − g_b`, and `v̇` is
//! free, so no relation between columns depends on `R` being a rotation.

use super::base_parameters::BaseParameters;
use super::expr::Expr;
use super::floating::{
    base_quaternion, coordinates, floating_base, floating_fields, flyer_inertial, world_gravity,
    BASE_COORDINATES,
};
use super::regressor::{self, body, ids, link_parameters, placeholder, ExactColumns, PARAMETERS};
use super::tracer::Tracer;
use super::{Equations, RegressorEquations};
use crate::algo::{self, Body, LinkFrame, Mat3, RobotScalars, Scalar, V3};
use crate::method::Family;
use crate::model::{Convention, FreeFlyer, Robot};
use crate::symbolic::{Graph, NodeId, Var};
use std::cell::RefCell;

impl Equations {
    /// Traces the regressor of the floating-base robot `robot` on the free flyer `flyer`
    /// ([`Equations::regressor`], its bodies the floating one and then the links) into the
    /// graph, after every other output, so that those keep their nodes.
    pub fn add_floating_regressor(&mut self, robot: &Robot, flyer: &FreeFlyer) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let fields = self.fields.clone();
        let mut tracer = Tracer::new(&graph, &fields, robot).shifted(BASE_COORDINATES);
        let tau = placeholder_tau(&mut tracer, robot, flyer);
        let parameters = std::iter::once(flyer_parameters(&tracer, flyer))
            .chain(robot.joints.iter().map(|j| link_parameters(&tracer, j)))
            .map(|pi| ids(&pi))
            .collect();
        let columns = regressor::columns(&mut graph.borrow_mut(), &tau, robot.dof() + 1);
        drop(tracer);
        self.graph = graph.into_inner();
        self.regressor = Some(RegressorEquations {
            columns,
            parameters,
            joint_columns: Vec::new(),
            joint_parameters: Vec::new(),
            rows: Vec::new(),
        });
        self.families = self.families.with(Family::FloatingRegressor);
    }

    /// The base parameters of the floating-base robot `robot` on `flyer`, tracing its regressor
    /// if it is not yet; `None` where the columns depend on a struct field (a length or angle).
    pub fn floating_base_parameters(
        &mut self,
        robot: &Robot,
        flyer: &FreeFlyer,
    ) -> Option<BaseParameters> {
        if self.regressor.is_none() {
            self.add_floating_regressor(robot, flyer);
        }
        self.grouped(&[], exact_floating_columns(robot, flyer))
    }
}

/// The regressor's columns alone, traced into a graph of their own with the description's
/// constants as leaves, and those leaves' values.
fn exact_floating_columns(robot: &Robot, flyer: &FreeFlyer) -> ExactColumns {
    let graph = RefCell::new(Graph::new());
    let fields = floating_fields(robot, flyer);
    let mut tracer = Tracer::new(&graph, &fields, robot)
        .with_exact_leaves()
        .shifted(BASE_COORDINATES);
    let tau = placeholder_tau(&mut tracer, robot, flyer);
    let columns = regressor::columns(&mut graph.borrow_mut(), &tau, robot.dof() + 1);
    let leaves = tracer.exact_leaf_values();
    drop(tracer);
    ExactColumns {
        graph: graph.into_inner(),
        columns,
        joint_columns: Vec::new(),
        rows: Vec::new(),
        leaves,
    }
}

/// τ of the floating base and the links, each body made of its placeholders: the floating
/// body's those of body 0, link j's those of body `j + 1`, carried into joint frame j.
fn placeholder_tau(tracer: &mut Tracer<'_>, robot: &Robot, flyer: &FreeFlyer) -> Vec<NodeId> {
    let mut chain = tracer.chain(robot);
    for (j, joint) in robot.joints.iter().enumerate() {
        let row = tracer.dh_row(j, joint);
        let (rotation, origin) = regressor::link_pose(tracer, &joint.link_pose);
        // The link frame in the chain's joint frame: D-H frame j there, then the link pose.
        let frame = match robot.convention {
            Convention::Standard => {
                let twist = Mat3::rot_x(row.sin_alpha, row.cos_alpha);
                LinkFrame {
                    rotation: twist.mul(&rotation),
                    origin: V3::new(row.a, row.a.zero(), row.a.zero()) + twist.mul_vec(origin),
                }
            }
            Convention::Modified => LinkFrame { rotation, origin },
        };
        chain.joints[j].body = frame.carry(&body(&placeholders(tracer, j + 1)));
    }
    let mut base = floating_base(tracer, robot, flyer);
    base.body = body(&placeholders(tracer, 0));
    let nv = robot.dof() + BASE_COORDINATES;
    let (v, a) = (
        coordinates(tracer, nv, Var::Qd),
        coordinates(tracer, nv, Var::Qdd),
    );
    let quaternion = base_quaternion(tracer);
    let gravity = world_gravity(tracer, flyer);
    ids(&algo::floating_rnea(
        &chain, &base, quaternion, &v, &a, gravity,
    ))
}

/// The ten placeholders of body `j` (0 the floating one).
fn placeholders<'g>(tracer: &Tracer<'g>, j: usize) -> [Expr<'g>; PARAMETERS] {
    std::array::from_fn(|k| tracer.var(Var::Inertial(placeholder(j, k))))
}

/// `π` of the floating body, about the base origin in base axes.
fn flyer_parameters<'g>(tracer: &Tracer<'g>, flyer: &FreeFlyer) -> [Expr<'g>; PARAMETERS] {
    let link = flyer_inertial(tracer, flyer);
    let zero = link.mass.zero();
    let body = Body::from_inertial(&link, zero, zero, zero.one());
    let [xx, yy, zz, xy, xz, yz] = body.inertia;
    let h = body.h;
    [body.mass, h.x, h.y, h.z, xx, xy, yy, xz, yz, zz]
}
