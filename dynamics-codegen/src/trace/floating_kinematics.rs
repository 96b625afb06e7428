//! The kinematic outputs of a tree on a free-flying base ([`algo::centroidal`],
//! [`algo::centroidal_bias`], [`algo::floating_frame`]) traced into the floating equations'
//! graph, in its coordinates ([`super::derive_floating`]: joint i at `6 + i`, the quaternion
//! `Q(2..6)`).
//!
//! The base position is not a coordinate of the graph (nothing else reads it), and enters the
//! positions only as a sum: the centre of mass and the frames' origins are traced relative to
//! the base origin, in world axes, and the base position is added where they are returned.

use super::cost::{ids, matrix_ids};
use super::floating::{base_quaternion, coordinates, floating_base, BASE_COORDINATES};
use super::mimic::Reduction;
use super::tracer::Tracer;
use super::Equations;
use crate::algo::{self, RobotScalars};
use crate::model::{FreeFlyer, Robot};
use crate::symbolic::{Graph, NodeId, Var};
use std::cell::RefCell;

/// The floating base's kinematic outputs, as node ids; `NV = n + 6` columns.
#[derive(Clone, Debug, Default)]
pub struct FloatingKinematicEquations {
    /// The centre of mass relative to the base origin, in world axes: 3.
    pub com: Vec<NodeId>,
    /// Its Jacobian in world axes, 3 × NV (Pinocchio's `jacobianCenterOfMass`).
    pub com_jacobian: Vec<Vec<NodeId>>,
    /// `A_G`, 6 × NV: `[linear; angular]` momentum about the CoM in world axes.
    pub centroidal_matrix: Vec<Vec<NodeId>>,
    /// `Ȧ_G v`: 6.
    pub centroidal_bias: Vec<NodeId>,
    /// The frames' names, in order ([`Robot::tip_frames`]).
    pub frame_names: Vec<String>,
    /// Each frame's rows `[R | p]`, 3 × 4, in the world, `p` relative to the base origin.
    pub frame_poses: Vec<Vec<Vec<NodeId>>>,
    /// Each frame's Jacobian in LOCAL_WORLD_ALIGNED, 6 × NV.
    pub jacobians_world: Vec<Vec<Vec<NodeId>>>,
    /// Each frame's Jacobian in LOCAL, 6 × NV.
    pub jacobians_local: Vec<Vec<Vec<NodeId>>>,
    /// Each frame's classical `J̇ v` in world axes: 6.
    pub biases_world: Vec<Vec<NodeId>>,
    /// Each frame's classical `J̇ v` in its own axes: 6.
    pub biases_local: Vec<Vec<NodeId>>,
}

impl Equations {
    /// Traces the kinematic outputs of `robot` on the free flyer `flyer` into the floating
    /// equations' graph ([`super::derive_floating`]'s), its frames [`Robot::tip_frames`].
    #[must_use]
    pub fn floating_kinematics(
        &mut self,
        robot: &Robot,
        flyer: &FreeFlyer,
    ) -> FloatingKinematicEquations {
        let graph = RefCell::new(std::mem::take(&mut self.graph));
        let fields = self.fields.clone();
        let mut tracer = Tracer::new(&graph, &fields, robot).shifted(BASE_COORDINATES);
        let chain = tracer.chain(robot);
        let base = floating_base(&tracer, robot, flyer);
        let nv = robot.dof() + BASE_COORDINATES;
        let v = coordinates(&tracer, nv, Var::Qd);
        let quaternion = base_quaternion(&tracer);
        let centroidal = algo::centroidal(&chain, &base, quaternion);
        let bias = algo::centroidal_bias(&chain, &base, quaternion, &v, centroidal.com_in_base);
        let c = centroidal.com;
        let mut out = FloatingKinematicEquations {
            com: ids(&[c.x, c.y, c.z]),
            com_jacobian: matrix_ids(&centroidal.com_jacobian),
            centroidal_matrix: matrix_ids(&centroidal.matrix),
            centroidal_bias: ids(&bias),
            ..FloatingKinematicEquations::default()
        };
        for tip in robot.tip_frames() {
            let k = algo::tip_kinematics(&mut tracer, robot, &tip);
            let fixed = algo::jacobian_in_base(&k);
            let fixed_bias = algo::acceleration_bias_in_base(&k, &fixed, &v[BASE_COORDINATES..]);
            let frame = algo::floating_frame(&k, &fixed, &fixed_bias, quaternion, &v);
            let pose = algo::Frame {
                rotation: frame.rotation,
                position: frame.position,
            };
            out.frame_names.push(tip.name.clone());
            out.frame_poses
                .push(matrix_ids(&pose.rows().map(Vec::from)));
            out.jacobians_world.push(matrix_ids(&frame.jacobian_world));
            out.jacobians_local.push(matrix_ids(&frame.jacobian_local));
            out.biases_world.push(ids(&frame.bias_world));
            out.biases_local.push(ids(&frame.bias_local));
        }
        let out = kinematics_in_coordinates(&graph, &tracer, robot, out);
        drop(tracer);
        self.graph = graph.into_inner();
        out
    }
}

/// The kinematics `k` in the coordinates of `robot` where it has mimic joints
/// ([`super::floating_mimic`]): the positions,
/// rotations and `J̇ v` substituted, the Jacobians' rows `J S̃` (`A_G S̃` for the centroidal
/// map); `tracer` the one that traced them.
fn kinematics_in_coordinates(
    graph: &RefCell<Graph>,
    tracer: &Tracer<'_>,
    robot: &Robot,
    k: FloatingKinematicEquations,
) -> FloatingKinematicEquations {
    if !robot.has_mimics() {
        return k;
    }
    let offsets = tracer.angle_offsets();
    let r = Reduction::shifted(graph, tracer, robot, &offsets, tracer.shift());
    let g = &mut graph.borrow_mut();
    let mut each = |rows: &[Vec<Vec<NodeId>>], jacobian: bool| -> Vec<Vec<Vec<NodeId>>> {
        rows.iter()
            .map(|m| match jacobian {
                true => r.rows(g, m),
                false => m.iter().map(|row| r.substitute(g, row)).collect(),
            })
            .collect()
    };
    let frame_poses = each(&k.frame_poses, false);
    let jacobians_world = each(&k.jacobians_world, true);
    let jacobians_local = each(&k.jacobians_local, true);
    let [com_jacobian, centroidal_matrix] = [&k.com_jacobian, &k.centroidal_matrix]
        .map(|m| each(std::slice::from_ref(m), true).remove(0));
    FloatingKinematicEquations {
        com: r.substitute(g, &k.com),
        com_jacobian,
        centroidal_matrix,
        centroidal_bias: r.substitute(g, &k.centroidal_bias),
        frame_names: k.frame_names,
        frame_poses,
        jacobians_world,
        jacobians_local,
        biases_world: k.biases_world.iter().map(|b| r.substitute(g, b)).collect(),
        biases_local: k.biases_local.iter().map(|b| r.substitute(g, b)).collect(),
    }
}
