//! The joint torque regressor (opt-in: traced only for a robot that asks for it,
//! `regressor = true`): the rigid bodies' part of inverse dynamics, `τ = Σ_j Y_j(q, q̇, q̈) π_j`,
//! with `π_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]` about the origin of link
//! frame j, in its axes (Pinocchio's `toDynamicParameters` order; off-diagonal entries `−∫xy dm`).
//!
//! Newton-Euler ([`algo::rnea`]) is traced once more, each link's body made of ten placeholders
//! ([`Var::Inertial`]) and carried from link frame j to the chain's joint frame as the chain
//! carries a described body ([`Body::from_inertial`]: turned by `Rotx(α_j)` and shifted by `a_j`
//! in the standard convention, as it is in the modified one). τ is linear in the placeholders,
//! so the column of `π_jk` is that trace with `π_jk = 1` and every other placeholder 0
//! ([`Graph::substitute`]), folded as it is rebuilt: no placeholder reaches the generated code.
//! The standard parameters come from the description: `m`, `m c`, and the inertia about the
//! centre of mass moved to the origin. The actuator inertia and the friction coefficients have
//! a column each per joint, `[q̈_i, q̇_i, sign(q̇_i), 1]`, beside the links'.

use super::expr::Expr;
use super::tracer::Tracer;
use super::Equations;
use crate::algo::{self, Body, Inertial, Mat3, RobotScalars, Scalar, V3};
use crate::method::Family;
use crate::model::{Convention, Robot};
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The parameters of a link, in `π`'s order.
const PARAMETERS: usize = 10;

/// The regressor's outputs: node ids into [`Equations::graph`].
#[derive(Clone, Debug)]
pub struct RegressorEquations {
    /// `columns[i][j][k] = ∂τ_i/∂π_jk`.
    pub columns: Vec<Vec<Vec<NodeId>>>,
    /// `parameters[j][k] = π_jk`, from the description.
    pub parameters: Vec<Vec<NodeId>>,
    /// Row i: `[q̈_i, q̇_i, sign(q̇_i) or tanh(q̇_i / ε), 1]`.
    pub joint_columns: Vec<Vec<NodeId>>,
    /// Row i: `[I_act, f_v, f_c, f_0]` of joint i, from the description.
    pub joint_parameters: Vec<Vec<NodeId>>,
}

impl Equations {
    /// Traces the regressor of `robot` ([`Equations::regressor`]) into the graph, after every
    /// other output, so that those keep their nodes.
    pub fn add_regressor(&mut self, robot: &Robot) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let fields = self.fields.clone();
        let mut tracer = Tracer::new(&graph, &fields, robot);
        let tau = placeholder_tau(&mut tracer, robot);
        let parameters = robot
            .joints
            .iter()
            .map(|joint| ids(&link_parameters(&tracer.inertial(joint))))
            .collect();
        let (joint_columns, joint_parameters) = joint_terms(&tracer, robot);
        let columns = columns(&mut graph.borrow_mut(), &tau);
        self.graph = graph.into_inner();
        self.regressor = Some(RegressorEquations {
            columns,
            parameters,
            joint_columns,
            joint_parameters,
        });
        self.families = self.families.with(Family::Regressor);
    }
}

/// τ of the rigid bodies, each link's body made of its placeholders.
fn placeholder_tau<'g>(tracer: &mut Tracer<'g>, robot: &Robot) -> Vec<NodeId> {
    let mut chain = tracer.chain(robot);
    for (j, joint) in robot.joints.iter().enumerate() {
        let row = tracer.dh_row(j, joint);
        let pi: [Expr<'g>; PARAMETERS] =
            std::array::from_fn(|k| tracer.var(Var::Inertial(placeholder(j, k))));
        let zero = row.a.zero();
        let (shift, sin_alpha, cos_alpha) = match robot.convention {
            Convention::Standard => (row.a, row.sin_alpha, row.cos_alpha),
            Convention::Modified => (zero, zero, zero.one()),
        };
        chain.joints[j].body = in_joint_frame(&pi, shift, sin_alpha, cos_alpha);
    }
    let n = robot.dof();
    let qd = tracer.joint_vars(n, Var::Qd);
    let qdd = tracer.joint_vars(n, Var::Qdd);
    let gravity = tracer.gravity(robot);
    ids(&algo::rnea(&chain, &qd, &qdd, gravity))
}

/// Per joint, the columns `[q̈_i, q̇_i, sign(q̇_i), 1]` of its actuator inertia and friction
/// coefficients (`tanh(q̇_i / ε)` for smoothed Coulomb friction, as `friction_torques` has it),
/// and those coefficients.
fn joint_terms(t: &Tracer<'_>, robot: &Robot) -> (Vec<Vec<NodeId>>, Vec<Vec<NodeId>>) {
    let zero = t.num(Number::ZERO);
    let one = t.num(Number::ONE);
    let rows = robot.joints.iter().enumerate().map(|(i, joint)| {
        let index = u16::try_from(i).unwrap_or(u16::MAX);
        let (qd, qdd) = (t.var(Var::Qd(index)), t.var(Var::Qdd(index)));
        let friction = joint.link.friction.as_ref();
        let direction = match friction.and_then(|f| f.smoothing.as_ref()) {
            None => t.sign(qd),
            Some(eps) => t.tanh(qd * t.reciprocal(&t.value(eps))),
        };
        let coefficients = friction.map_or([zero; 3], |f| {
            [t.value(&f.viscous), t.value(&f.coulomb), t.value(&f.offset)]
        });
        let actuator = t.value(&joint.link.actuator_inertia);
        (
            ids(&[qdd, qd, direction, one]),
            ids(&[actuator, coefficients[0], coefficients[1], coefficients[2]]),
        )
    });
    rows.unzip()
}

/// The placeholder of parameter `k` of link `j`.
fn placeholder(j: usize, k: usize) -> u16 {
    u16::try_from(j * PARAMETERS + k).unwrap_or(u16::MAX)
}

/// The body of `π` (about link frame j's origin, in its axes) about the joint frame's origin:
/// turned by `Rotx(α)`, then seen from the origin `shift` along x before it.
fn in_joint_frame<S: Scalar>(
    pi: &[S; PARAMETERS],
    shift: S,
    sin_alpha: S,
    cos_alpha: S,
) -> Body<S> {
    let [m, mx, my, mz, ixx, ixy, iyy, ixz, iyz, izz] = *pi;
    let rot = Mat3::rot_x(sin_alpha, cos_alpha);
    let turned = Body {
        mass: m,
        h: rot.mul_vec(V3::new(mx, my, mz)),
        inertia: Mat3::symmetric([ixx, iyy, izz, ixy, ixz, iyz]).congruence(&rot),
    };
    let zero = shift.zero();
    turned.moved_by(V3::new(shift, zero, zero))
}

/// `π` of a described link: `m`, `m c`, and `I_O = I_C + m(cᵀc·1 − c cᵀ)` (the tensor's
/// entries, off-diagonal `−∫xy dm`), in `π`'s order.
fn link_parameters<S: Scalar>(link: &Inertial<S>) -> [S; PARAMETERS] {
    let zero = link.mass.zero();
    let origin = Body::from_inertial(link, zero, zero, zero.one());
    let [xx, yy, zz, xy, xz, yz] = origin.inertia;
    let h = origin.h;
    [origin.mass, h.x, h.y, h.z, xx, xy, yy, xz, yz, zz]
}

/// `columns[i][j][k]`: τ_i with `π_jk = 1` and every other placeholder 0.
fn columns(g: &mut Graph, tau: &[NodeId]) -> Vec<Vec<Vec<NodeId>>> {
    let n = tau.len();
    let (zero, one) = (g.num(Number::ZERO), g.num(Number::ONE));
    // by_parameter[j][k][i]: the column of π_jk, row i.
    let by_parameter: Vec<Vec<Vec<NodeId>>> = (0..n)
        .map(|j| {
            (0..PARAMETERS)
                .map(|k| {
                    let chosen = placeholder(j, k);
                    g.substitute(tau, |v| match v {
                        Var::Inertial(p) => Some(if p == chosen { one } else { zero }),
                        _ => None,
                    })
                })
                .collect()
        })
        .collect();
    (0..n)
        .map(|i| {
            let link = |columns: &Vec<Vec<NodeId>>| columns.iter().map(|c| c[i]).collect();
            by_parameter.iter().map(link).collect()
        })
        .collect()
}

fn ids(values: &[Expr<'_>]) -> Vec<NodeId> {
    values.iter().map(|e| e.id()).collect()
}
