//! Mimic joints: the outputs of a robot whose joint m follows `q_m = k q_j + o` in its reduced
//! coordinates (every joint but the mimic ones, in order), as Pinocchio 4's mimic joints.
//!
//! The algorithms run on every joint, each with its own leaves, as for a robot without mimics;
//! then (1) each joint's leaves are replaced by the coordinates' (`q_m = k q_j + o`,
//! `q̇_m = k q̇_j`, `q̈_m = k q̈_j`, the sine and cosine of `k q_j + o` and m's angle offset, or
//! `±sin q_j`, `cos q_j` where k = ±1, o = 0 and neither joint has an offset), and (2) each
//! output is projected with the constant map S (joints × coordinates: row m is `k e_j`):
//! `Sᵀ τ`, `Sᵀ M S`, `Sᵀ C S` (Christoffel's, so `Ṁ = C + Cᵀ` still holds), the Jacobians'
//! rows `J S`, the energies as they are. Derivatives by the coordinates, traced afterwards on the
//! reduced graph, follow by the chain rule.
//!
//! On a floating base ([`Reduction::shifted`]) the map is `S̃ = diag(1₆, S)`: the base's six
//! velocity coordinates, numbered before the joints, are their own, so `S̃ᵀ M S̃`, `S̃ᵀ τ`, `J S̃`.

use super::kinematics::KinematicEquations;
use super::tracer::{joint_index, Tracer};
use crate::algo::RobotScalars;
use crate::model::Robot;
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;

/// The map from joints to coordinates, and each joint's leaves in the coordinates' terms.
pub(super) struct Reduction {
    /// Per index (the `shift` coordinates of a floating base, then the joints), its
    /// coordinate (a mimic joint's: that of the joint it follows).
    coordinate: Vec<usize>,
    /// Per index, its column of S: `None` for 1 (a coordinate), `Some(k)` for a mimic joint.
    factor: Vec<Option<NodeId>>,
    /// Per coordinate, its index.
    joints: Vec<usize>,
    /// Per joint, the nodes replacing its leaves `q`, `sin q`, `cos q`, `q̇`, `q̈`.
    leaves: Vec<[NodeId; 5]>,
    /// The coordinates before the joints, their own (a floating base's six), whose leaves stay.
    shift: usize,
}

impl Reduction {
    /// The reduction of `robot` (which has mimic joints); `angle_offsets` as the tracer
    /// recorded them, per joint.
    pub(super) fn new(
        graph: &RefCell<Graph>,
        tracer: &Tracer<'_>,
        robot: &Robot,
        angle_offsets: &[Option<NodeId>],
    ) -> Reduction {
        Reduction::shifted(graph, tracer, robot, angle_offsets, 0)
    }

    /// The reduction of `robot` whose joint i is at index `shift + i` of the leaves and the
    /// outputs, after `shift` coordinates of its own (a floating base's six: `S̃ = diag(1, S)`);
    /// `angle_offsets` per index, as the shifted tracer recorded them.
    pub(super) fn shifted(
        graph: &RefCell<Graph>,
        tracer: &Tracer<'_>,
        robot: &Robot,
        angle_offsets: &[Option<NodeId>],
        shift: usize,
    ) -> Reduction {
        let joints: Vec<usize> = (0..shift)
            .chain(robot.coordinates().into_iter().map(|j| shift + j))
            .collect();
        let mut coordinate: Vec<usize> = (0..shift + robot.dof()).collect();
        for (c, &j) in joints.iter().enumerate() {
            coordinate[j] = c;
        }
        let mut factor = vec![None; shift + robot.dof()];
        let mut leaves = Vec::with_capacity(robot.dof());
        for (joint_number, joint) in robot.joints.iter().enumerate() {
            let i = shift + joint_number;
            let followed = shift + joint.mimic.as_ref().map_or(joint_number, |m| m.joint);
            coordinate[i] = coordinate[followed];
            let c = joint_index(coordinate[i]);
            let mut g = graph.borrow_mut();
            let own = [
                Var::Q(c),
                Var::SinQ(c),
                Var::CosQ(c),
                Var::Qd(c),
                Var::Qdd(c),
            ];
            let own = own.map(|v| g.var(v));
            drop(g);
            let Some(mimic) = &joint.mimic else {
                leaves.push(own);
                continue;
            };
            let k = tracer.value(&mimic.multiplier).id();
            let o = tracer.value(&mimic.offset).id();
            factor[i] = Some(k);
            let mut g = graph.borrow_mut();
            let [q, sin, cos, qd, qdd] = own;
            let kq = g.mul(k, q);
            let q_m = g.add(kq, o);
            let unit = g.constant(k).filter(|k| k.is_one() || k.is_minus_one());
            let plain = angle_offsets[i].is_none() && angle_offsets[followed].is_none();
            let (sin, cos) = match unit {
                Some(k) if plain && g.is_zero(o) && k.is_one() => (sin, cos),
                Some(_) if plain && g.is_zero(o) => (g.neg(sin), cos),
                _ => {
                    let angle = angle_offsets[i].map_or(q_m, |offset| g.add(q_m, offset));
                    (g.sin(angle), g.cos(angle))
                }
            };
            leaves.push([q_m, sin, cos, g.mul(k, qd), g.mul(k, qdd)]);
        }
        Reduction {
            coordinate,
            factor,
            joints,
            leaves,
            shift,
        }
    }

    /// Number of coordinates (the shifted ones included).
    pub(super) fn coordinates(&self) -> usize {
        self.joints.len()
    }

    /// Per index, its coordinate (a mimic joint's: that of the joint it follows).
    pub(super) fn coordinate_of_joints(&self) -> &[usize] {
        &self.coordinate
    }

    /// `S_ic · x`, index i's term in its coordinate c's row of `Sᵀ v` (`x` substituted).
    pub(super) fn scaled(&self, g: &mut Graph, joint: usize, x: NodeId) -> NodeId {
        match self.factor[joint] {
            Some(k) => g.mul(k, x),
            None => x,
        }
    }

    /// Per coordinate, its index's entry of `per_joint` (one per index).
    pub(super) fn of_coordinates<T: Clone>(&self, per_joint: &[T]) -> Vec<T> {
        self.joints.iter().map(|&j| per_joint[j].clone()).collect()
    }

    /// `ids` in the coordinates: every joint's leaves replaced.
    pub(super) fn substitute(&self, g: &mut Graph, ids: &[NodeId]) -> Vec<NodeId> {
        let leaf = |v: Var| {
            let (i, k) = match v {
                Var::Q(i) => (i, 0),
                Var::SinQ(i) => (i, 1),
                Var::CosQ(i) => (i, 2),
                Var::Qd(i) => (i, 3),
                Var::Qdd(i) => (i, 4),
                _ => return None,
            };
            let joint = usize::from(i).checked_sub(self.shift)?;
            self.leaves.get(joint).map(|l| l[k])
        };
        g.substitute(ids, leaf)
    }

    /// `Sᵀ v` of a vector per joint (already substituted).
    pub(super) fn project(&self, g: &mut Graph, v: &[NodeId]) -> Vec<NodeId> {
        let mut out: Vec<Option<NodeId>> = vec![None; self.coordinates()];
        for (i, &x) in v.iter().enumerate() {
            let term = self.scaled(g, i, x);
            let slot = &mut out[self.coordinate[i]];
            *slot = Some(match *slot {
                Some(sum) => g.add(sum, term),
                None => term,
            });
        }
        let zero = g.num(Number::ZERO);
        out.into_iter().map(|x| x.unwrap_or(zero)).collect()
    }

    /// `Sᵀ v` of a vector per joint in the joints' leaves.
    pub(super) fn vector(&self, g: &mut Graph, v: &[NodeId]) -> Vec<NodeId> {
        let v = self.substitute(g, v);
        self.project(g, &v)
    }

    /// Each row projected, `A S` (a Jacobian's rows, 6 × joints).
    pub(super) fn rows(&self, g: &mut Graph, rows: &[Vec<NodeId>]) -> Vec<Vec<NodeId>> {
        rows.iter().map(|r| self.vector(g, r)).collect()
    }

    /// `Sᵀ M S`.
    pub(super) fn matrix(&self, g: &mut Graph, m: &[Vec<NodeId>]) -> Vec<Vec<NodeId>> {
        let rows = self.rows(g, m);
        let columns = transpose(&rows);
        let projected: Vec<Vec<NodeId>> = columns.iter().map(|c| self.project(g, c)).collect();
        transpose(&projected)
    }

    /// `Γ_abc = Σ S_ia S_jb S_kc Γ_ijk`.
    pub(super) fn christoffel(
        &self,
        g: &mut Graph,
        symbols: &[Vec<Vec<NodeId>>],
    ) -> Vec<Vec<Vec<NodeId>>> {
        // Over j and k row by row (each `Γ_i` a matrix), then over i element by element.
        let inner: Vec<Vec<Vec<NodeId>>> = symbols.iter().map(|s| self.matrix(g, s)).collect();
        let n = self.coordinates();
        let zero = g.num(Number::ZERO);
        let mut out = vec![vec![vec![zero; n]; n]; n];
        for b in 0..n {
            for c in 0..n {
                let column: Vec<NodeId> = inner.iter().map(|s| s[b][c]).collect();
                for (a, x) in self.project(g, &column).into_iter().enumerate() {
                    out[a][b][c] = x;
                }
            }
        }
        out
    }

    /// The kinematics in the coordinates: the Jacobians `J S`, the torques `Sᵀ Jᵀ F`, the
    /// poses and `J̇ q̇` substituted; the link poses of the coordinates' joints.
    pub(super) fn kinematics(&self, g: &mut Graph, k: &KinematicEquations) -> KinematicEquations {
        let poses = |g: &mut Graph, rows: &[Vec<NodeId>]| -> Vec<Vec<NodeId>> {
            rows.iter().map(|r| self.substitute(g, r)).collect()
        };
        let link_poses = self.of_coordinates(&k.link_poses);
        KinematicEquations {
            hand_pose: poses(g, &k.hand_pose),
            link_poses: link_poses.iter().map(|p| poses(g, p)).collect(),
            jacobian_in_base: self.rows(g, &k.jacobian_in_base),
            jacobian_in_hand: self.rows(g, &k.jacobian_in_hand),
            bias_in_base: self.substitute(g, &k.bias_in_base),
            bias_in_hand: self.substitute(g, &k.bias_in_hand),
            torques_for_hand_wrench: self.vector(g, &k.torques_for_hand_wrench),
            torques_for_base_wrench: self.vector(g, &k.torques_for_base_wrench),
        }
    }
}

fn transpose(rows: &[Vec<NodeId>]) -> Vec<Vec<NodeId>> {
    let columns = rows.first().map_or(0, Vec::len);
    (0..columns)
        .map(|j| rows.iter().map(|r| r[j]).collect())
        .collect()
}
