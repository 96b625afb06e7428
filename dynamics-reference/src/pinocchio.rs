//! Reads the record of a Pinocchio model that `tests/data/trees/make.py` writes
//! (`pinocchio_model`: per joint its parent, Pinocchio's joint type, the placement in the
//! parent's frame and the body's inertia; the tips' frames) as a URDF-style [`Robot`].

use nalgebra::Matrix4;
use serde::Deserialize;

use crate::kinematics::placement_matrix;
use crate::robot::{Convention, Joint, JointKind, Placement, Robot};

/// One joint of the record.
#[derive(Deserialize)]
struct RecordJoint {
    name: String,
    /// 1-based index of the parent joint, 0 for the base (Pinocchio's `model.parents`).
    parent: usize,
    #[serde(rename = "type")]
    kind: String,
    rotation: [[f64; 3]; 3],
    translation: [f64; 3],
    mass: f64,
    /// Centre of mass in the joint frame.
    lever: [f64; 3],
    /// Inertia tensor about the centre of mass, in the joint frame's axes.
    inertia: [[f64; 3]; 3],
    /// The axis of an `…Unaligned` joint.
    axis: Option<[f64; 3]>,
}

#[derive(Deserialize)]
struct RecordFrame {
    name: String,
    parent: usize,
    rotation: [[f64; 3]; 3],
    translation: [f64; 3],
}

#[derive(Deserialize)]
struct Record {
    gravity: [f64; 3],
    joints: Vec<RecordJoint>,
    #[serde(default)]
    frames: Vec<RecordFrame>,
}

/// A frame fixed on a link of a robot read by [`Robot::from_pinocchio_model`] (a tip).
#[derive(Debug, Clone, PartialEq)]
pub struct PinocchioFrame {
    /// Its name (a URDF link's).
    pub name: String,
    /// The link (0-based joint index) that carries it.
    pub link: usize,
    /// Its pose in that link's frame, for [`Robot::frame_jacobian`].
    pub offset: Matrix4<f64>,
}

impl RecordJoint {
    /// Joint `i` of a URDF-style robot.
    fn joint(&self, i: usize) -> Result<Joint, String> {
        let at = || format!("joint {i} ({:?})", self.name);
        let (kind, axis) = match self.kind.as_str() {
            "JointModelRX" => (JointKind::Revolute, [1.0, 0.0, 0.0]),
            "JointModelRY" => (JointKind::Revolute, [0.0, 1.0, 0.0]),
            "JointModelRZ" => (JointKind::Revolute, [0.0, 0.0, 1.0]),
            "JointModelPX" => (JointKind::Prismatic, [1.0, 0.0, 0.0]),
            "JointModelPY" => (JointKind::Prismatic, [0.0, 1.0, 0.0]),
            "JointModelPZ" => (JointKind::Prismatic, [0.0, 0.0, 1.0]),
            "JointModelRevoluteUnaligned" | "JointModelPrismaticUnaligned" => {
                let kind = if self.kind.starts_with("JointModelRevolute") {
                    JointKind::Revolute
                } else {
                    JointKind::Prismatic
                };
                let axis = self
                    .axis
                    .ok_or_else(|| format!("{}: {} without `axis`", at(), self.kind))?;
                (kind, axis)
            }
            other => return Err(format!("{}: unknown joint type {other:?}", at())),
        };
        if self.parent > i {
            return Err(format!(
                "{}: parent {} does not come before it",
                at(),
                self.parent
            ));
        }
        let m = &self.inertia;
        let symmetric =
            (m[0][1] - m[1][0]).abs() + (m[0][2] - m[2][0]).abs() + (m[1][2] - m[2][1]).abs();
        if symmetric > 1e-12 * (m[0][0].abs() + m[1][1].abs() + m[2][2].abs()) {
            return Err(format!("{}: inertia {m:?} is not symmetric", at()));
        }
        Ok(Joint {
            kind,
            theta: 0.0,
            d: 0.0,
            a: 0.0,
            alpha: 0.0,
            parent: self.parent.checked_sub(1),
            gamma: 0.0,
            b: 0.0,
            placement: Some(Placement {
                rotation: self.rotation,
                xyz: self.translation,
                axis,
            }),
            mass: self.mass,
            com: self.lever,
            inertia: [m[0][0], m[1][1], m[2][2], m[0][1], m[0][2], m[1][2]],
            actuator_inertia: 0.0,
            spring_stiffness: 0.0,
            spring_rest: 0.0,
        })
    }
}

impl Robot {
    /// A URDF-style robot from the record of a Pinocchio model (`pinocchio_model` of
    /// `tests/data/trees/*.json`: `gravity`; per joint `name`, `parent` (1-based, 0 the base),
    /// `type` (`JointModelR{X,Y,Z}`, `JointModelP{X,Y,Z}`, `JointModel{Revolute,Prismatic}
    /// Unaligned` with `axis`), `rotation`, `translation` (the placement in the parent's
    /// frame), `mass`, `lever` (the centre of mass) and `inertia` (3×3, about the centre of
    /// mass); per frame `name`, `parent`, `rotation`, `translation`), and its frames.
    ///
    /// # Errors
    ///
    /// If the text does not match the record, a joint type is unknown, a parent does not
    /// come before its joint, an inertia is not symmetric, or the robot does not pass
    /// [`Robot::check`] (a non-unit axis, a rotation that is not one); the message names the joint.
    pub fn from_pinocchio_model(
        name: &str,
        json: &str,
    ) -> Result<(Robot, Vec<PinocchioFrame>), String> {
        let record: Record = serde_json::from_str(json).map_err(|e| e.to_string())?;
        let joints = record
            .joints
            .iter()
            .enumerate()
            .map(|(i, j)| j.joint(i))
            .collect::<Result<Vec<Joint>, String>>()?;
        let robot = Robot {
            name: name.to_owned(),
            description: "read from a Pinocchio model".to_owned(),
            convention: Convention::Urdf,
            gravity: record.gravity,
            joints,
        };
        robot.check()?;
        let frames = record
            .frames
            .iter()
            .map(|f| {
                let link = f
                    .parent
                    .checked_sub(1)
                    .filter(|&l| l < robot.dof())
                    .ok_or_else(|| {
                        format!("frame {:?}: parent {} is not a joint", f.name, f.parent)
                    })?;
                let placement = Placement {
                    rotation: f.rotation,
                    xyz: f.translation,
                    axis: [0.0, 0.0, 1.0],
                };
                Ok(PinocchioFrame {
                    name: f.name.clone(),
                    link,
                    offset: placement_matrix(&placement),
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        Ok((robot, frames))
    }
}
