//! The joint torque regressor (opt-in: traced only for a robot that asks for it,
//! `regressor = true`): the rigid bodies' part of inverse dynamics, `τ = Σ_j Y_j(q, q̇, q̈) π_j`,
//! with `π_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]` about the origin of link
//! frame j, in its axes (Pinocchio's `toDynamicParameters` order; off-diagonal entries `−∫xy dm`):
//! the D-H frame of a robot given by its table, the file's frame of one given by joint frames or
//! a URDF.
//!
//! τ is traced by projection ([`algo::projected_torques`]: each joint's unit motion carried out
//! to the links it moves, dotted with their wrenches written as linear in their parameters),
//! each link's body made of ten placeholders ([`Var::Inertial`]). Two ways, the one whose
//! columns take fewer operations kept: the bodies carried from link frame j to the chain's joint
//! frame (through D-H frame j, `Joint::link_pose`, then turned by `Rotx(α_j)` and shifted by
//! `a_j` in the standard convention, as the chain carries a described body,
//! [`Body::from_inertial`]) and regrouped as `M` and τ are (the dense arms: PUMA 560, the
//! Panda), or left in the link frames, the rates carried there instead, so that no column mixes
//! the parameters of a frame turned by an arbitrary twist (random5). τ is linear in the
//! placeholders, so the column of `π_jk` is that trace with `π_jk = 1` and every other
//! placeholder 0 ([`Graph::substitute`]), folded as it is rebuilt: no placeholder reaches the
//! generated code. The standard parameters come from the description: `m`, `m c`, and the
//! inertia about the centre of mass moved to the origin. The actuator inertia and the friction
//! coefficients have a column each per joint, `[q̈_i, q̇_i, sign(q̇_i), 1]`, beside the links'.
//!
//! A robot with mimic joints has a row per coordinate and still a column per link: `Sᵀ Y` with
//! the joints' leaves replaced ([`super::mimic`]), each mimic link keeping its own parameters;
//! a mimic joint's own columns are those of `k q̇_j` (and `k q̈_j`), times k, in its
//! coordinate's row.

use super::cost;
use super::expr::Expr;
use super::mimic::Reduction;
use super::tracer::Tracer;
use super::Equations;
use crate::algo::{self, Body, LinkFrame, LinkFrames, Mat3, RobotScalars, Scalar, Twist, V3};
use crate::method::Family;
use crate::model::{Convention, Joint, Pose, Robot};
use crate::symbolic::modular::Fp;
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The parameters of a link, in `π`'s order.
pub(super) const PARAMETERS: usize = 10;

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
    /// Per joint, the row of τ its joint columns add to: its coordinate (i itself but on a
    /// robot with mimic joints).
    pub rows: Vec<usize>,
}

impl Equations {
    /// Traces the regressor of `robot` ([`Equations::regressor`]) into the graph, after every
    /// other output, so that those keep their nodes.
    pub fn add_regressor(&mut self, robot: &Robot) {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let fields = self.fields.clone();
        let mut tracer = Tracer::new(&graph, &fields, robot);
        let candidates = placeholder_taus(&mut tracer, robot, true);
        let parameters = robot
            .joints
            .iter()
            .map(|joint| ids(&link_parameters(&tracer, joint)))
            .collect();
        let (joint_columns, joint_parameters) = joint_terms(&tracer, robot);
        let columns = cheapest_columns(&mut graph.borrow_mut(), &candidates);
        let (columns, joint_columns, rows) =
            in_coordinates(&graph, &tracer, robot, columns, joint_columns);
        drop(tracer);
        self.graph = graph.into_inner();
        self.regressor = Some(RegressorEquations {
            columns,
            parameters,
            joint_columns,
            joint_parameters,
            rows,
        });
        self.families = self.families.with(Family::Regressor);
    }
}

/// Link columns (`[row][link][k]`), joint columns (per joint) and each joint's row.
type InCoordinates = (Vec<Vec<Vec<NodeId>>>, Vec<Vec<NodeId>>, Vec<usize>);

/// The columns (`columns[i][j][k]` of joint i's torque) and joint columns in the coordinates
/// of `robot`: as they are for a robot without mimic joints; else each link's column `Sᵀ Y_jk`
/// with the joints' leaves replaced, each joint's columns with its leaves replaced, times its
/// entry of S, in its coordinate's row.
fn in_coordinates(
    graph: &RefCell<Graph>,
    tracer: &Tracer<'_>,
    robot: &Robot,
    columns: Vec<Vec<Vec<NodeId>>>,
    joint_columns: Vec<Vec<NodeId>>,
) -> InCoordinates {
    if !robot.has_mimics() {
        return (columns, joint_columns, (0..robot.dof()).collect());
    }
    let reduction = Reduction::new(graph, tracer, robot, &tracer.angle_offsets());
    let g = &mut graph.borrow_mut();
    let links = robot.dof();
    // One substitution for all, then each link parameter's column projected.
    let by_parameter: Vec<NodeId> = (0..links)
        .flat_map(|j| (0..PARAMETERS).map(move |k| (j, k)))
        .flat_map(|(j, k)| columns.iter().map(move |row| row[j][k]))
        .collect();
    let substituted = reduction.substitute(g, &by_parameter);
    let zero = g.num(Number::ZERO);
    let mut reduced = vec![vec![vec![zero; PARAMETERS]; links]; reduction.coordinates()];
    for (p, column) in substituted.chunks(links).enumerate() {
        let (j, k) = (p / PARAMETERS, p % PARAMETERS);
        for (c, x) in reduction.project(g, column).into_iter().enumerate() {
            reduced[c][j][k] = x;
        }
    }
    let joint_columns = joint_columns
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let row = reduction.substitute(g, row);
            row.iter().map(|&x| reduction.scaled(g, i, x)).collect()
        })
        .collect();
    let rows = reduction.coordinate_of_joints().to_vec();
    (reduced, joint_columns, rows)
}

/// The regressor's columns and joint columns alone, traced into a graph of their own with the
/// description's constants as leaves ([`Tracer::with_exact_leaves`]), and those leaves' values.
pub(super) fn exact_columns(robot: &Robot) -> ExactColumns {
    let graph = RefCell::new(Graph::new());
    let fields = robot.fields();
    let mut tracer = Tracer::new(&graph, &fields, robot).with_exact_leaves();
    // The bodies carried into the joint frames only: carrying a body changes π's coordinates,
    // which keeps the columns' relations, where the rates carried into the link frames would
    // need a link pose's turn to be exactly orthogonal, as its entries as leaves are not.
    let tau = placeholder_taus(&mut tracer, robot, false).swap_remove(0);
    let (joint_columns, _) = joint_terms(&tracer, robot);
    let columns = columns(&mut graph.borrow_mut(), &tau, robot.dof());
    // The reduced rows, so that parameters the coupling makes inseparable are grouped.
    let (columns, joint_columns, rows) =
        in_coordinates(&graph, &tracer, robot, columns, joint_columns);
    let leaves = tracer.exact_leaf_values();
    drop(tracer);
    ExactColumns {
        graph: graph.into_inner(),
        columns,
        joint_columns,
        rows,
        leaves,
    }
}

/// What [`exact_columns`] traces.
pub(super) struct ExactColumns {
    pub graph: Graph,
    /// As [`RegressorEquations::columns`].
    pub columns: Vec<Vec<Vec<NodeId>>>,
    /// As [`RegressorEquations::joint_columns`].
    pub joint_columns: Vec<Vec<NodeId>>,
    /// As [`RegressorEquations::rows`].
    pub rows: Vec<usize>,
    /// The value of leaf [`Var::Exact`]`(k)`.
    pub leaves: Vec<Fp>,
}

/// τ of the rigid bodies, each link's body made of its placeholders: the bodies carried into
/// the joint frames and regrouped, then, `with_link_frames`, the bodies left in the link frames.
fn placeholder_taus(
    tracer: &mut Tracer<'_>,
    robot: &Robot,
    with_link_frames: bool,
) -> Vec<Vec<NodeId>> {
    let mut in_joint_frames = tracer.chain(robot);
    let mut in_link_frames = in_joint_frames.clone();
    let mut poses = Vec::with_capacity(robot.dof());
    let mut tip_twist = None;
    for (j, joint) in robot.joints.iter().enumerate() {
        let row = tracer.dh_row(j, joint);
        let pi = std::array::from_fn(|k| tracer.var(Var::Inertial(placeholder(j, k))));
        let (rotation, origin) = link_pose(tracer, &joint.link_pose);
        let pose = LinkFrame { rotation, origin };
        let zero = row.a.zero();
        // The link frame in the chain's joint frame: D-H frame j there, then the link pose.
        let frame = match robot.convention {
            Convention::Standard => {
                let twist = Mat3::rot_x(row.sin_alpha, row.cos_alpha);
                tip_twist = Some(Twist {
                    a: row.a,
                    sin_alpha: row.sin_alpha,
                    cos_alpha: row.cos_alpha,
                });
                LinkFrame {
                    rotation: twist.mul(&rotation),
                    origin: V3::new(row.a, zero, zero) + twist.mul_vec(origin),
                }
            }
            Convention::Modified => pose,
        };
        in_link_frames.joints[j].body = body(&pi);
        in_joint_frames.joints[j].body = frame.carry(&body(&pi));
        poses.push(pose);
    }
    let n = robot.dof();
    let qd = tracer.joint_vars(n, Var::Qd);
    let qdd = tracer.joint_vars(n, Var::Qdd);
    let gravity = tracer.gravity(robot);
    let regrouped = in_joint_frames.regrouped();
    let tau = |chain, frames| ids(&algo::projected_torques(chain, frames, &qd, &qdd, gravity));
    let mut taus = vec![tau(&regrouped, None)];
    if with_link_frames {
        // Carried through the D-H frames, a standard table's link frames before their poses.
        let frames = LinkFrames {
            tip_twist,
            poses: &poses,
        };
        taus.push(tau(&in_link_frames, Some(&frames)));
    }
    taus
}

/// `π` of link `joint`, about the origin of its link frame, in its axes: the description's
/// body in D-H frame i, carried back into the link frame (the same frame for a D-H table).
pub(super) fn link_parameters<'g>(tracer: &Tracer<'g>, joint: &Joint) -> [Expr<'g>; PARAMETERS] {
    let link = tracer.inertial(joint);
    let zero = link.mass.zero();
    let in_dh_frame = Body::from_inertial(&link, zero, zero, zero.one());
    let (rotation, origin) = link_pose(tracer, &joint.link_pose);
    let back = in_dh_frame.moved_by(origin.scale(-zero.one()));
    let back_in_link_axes = LinkFrame {
        rotation: rotation.transpose(),
        origin: V3::zero(zero),
    };
    let turned = back_in_link_axes.carry(&back);
    let [xx, yy, zz, xy, xz, yz] = turned.inertia;
    let h = turned.h;
    [turned.mass, h.x, h.y, h.z, xx, xy, yy, xz, yz, zz]
}

/// The link frame in D-H frame i: its axes (columns) and its origin.
pub(super) fn link_pose<'g>(tracer: &Tracer<'g>, pose: &Pose) -> (Mat3<Expr<'g>>, V3<Expr<'g>>) {
    let v = |x| tracer.value(x);
    let t = &pose.translation;
    let rotation = Mat3 {
        m: pose.rotation.each_ref().map(|row| row.each_ref().map(v)),
    };
    (rotation, V3::new(v(&t[0]), v(&t[1]), v(&t[2])))
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
pub(super) fn placeholder(j: usize, k: usize) -> u16 {
    u16::try_from(j * PARAMETERS + k).unwrap_or(u16::MAX)
}

/// The body of `π`, about the origin of the frame it is given in, in its axes.
pub(super) fn body<S: Scalar>(pi: &[S; PARAMETERS]) -> Body<S> {
    let [m, mx, my, mz, ixx, ixy, iyy, ixz, iyz, izz] = *pi;
    Body {
        mass: m,
        h: V3::new(mx, my, mz),
        inertia: [ixx, iyy, izz, ixy, ixz, iyz],
    }
}

/// Of the columns of each way of tracing τ ([`placeholder_taus`]), those that take the fewest
/// operations.
fn cheapest_columns(g: &mut Graph, candidates: &[Vec<NodeId>]) -> Vec<Vec<Vec<NodeId>>> {
    let candidates: Vec<_> = candidates
        .iter()
        .map(|tau| columns(g, tau, tau.len()))
        .collect();
    let mut candidates = candidates.into_iter();
    let first = candidates.next().unwrap_or_default();
    cost::cheapest(g, first, candidates, |c| {
        c.iter().flatten().flatten().copied().collect()
    })
}

/// `columns[i][j][k]`: τ_i with `π_jk = 1` and every other placeholder 0, for the `links`
/// bodies whose placeholders τ reads.
pub(super) fn columns(g: &mut Graph, tau: &[NodeId], links: usize) -> Vec<Vec<Vec<NodeId>>> {
    let (zero, one) = (g.num(Number::ZERO), g.num(Number::ONE));
    let inertial = g.dependents(tau, |v| matches!(v, Var::Inertial(_)));
    // by_parameter[j][k][i]: the column of π_jk, row i.
    let by_parameter: Vec<Vec<Vec<NodeId>>> = (0..links)
        .map(|j| {
            (0..PARAMETERS)
                .map(|k| {
                    let chosen = placeholder(j, k);
                    g.substitute_within(tau, &inertial, |v| match v {
                        Var::Inertial(p) => Some(if p == chosen { one } else { zero }),
                        _ => None,
                    })
                })
                .collect()
        })
        .collect();
    (0..tau.len())
        .map(|i| {
            let link = |columns: &Vec<Vec<NodeId>>| columns.iter().map(|c| c[i]).collect();
            by_parameter.iter().map(link).collect()
        })
        .collect()
}

pub(super) fn ids(values: &[Expr<'_>]) -> Vec<NodeId> {
    values.iter().map(|e| e.id()).collect()
}
