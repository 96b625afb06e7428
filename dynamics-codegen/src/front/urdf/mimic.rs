//! Mimic joints: each moving joint's `<mimic joint multiplier offset>` as the model's
//! [`Mimic`], the joint it follows found among the robot's joints. Refused, at the `<mimic>`:
//! a joint the file does not have or the robot does not keep (fixed, or cut off by `tip` or
//! `tips`), the joint itself, a joint that is a mimic joint too, and a joint of the other kind
//! (revolute and prismatic: Pinocchio follows a joint of the same kind only).

use super::xml::{error, Description, Kind};
use crate::front::errors::FileError;
use crate::model::{Joint, Mimic};

/// Sets the mimic rule of `joints`, the robot's joints made of the URDF joints `urdf_joints`
/// (indices into `doc.joints`, in the same order).
pub(super) fn resolve(
    doc: &Description,
    urdf_joints: &[usize],
    joints: &mut [Joint],
) -> Vec<FileError> {
    let mut errors = Vec::new();
    for (i, &u) in urdf_joints.iter().enumerate() {
        let joint = &doc.joints[u];
        let Some(mimic) = &joint.mimic else { continue };
        let (name, followed) = (&joint.name, &mimic.joint);
        let prefix = format!("joint `{name}`'s `<mimic joint=\"{followed}\">`");
        let robot_index = urdf_joints
            .iter()
            .position(|&v| doc.joints[v].name == *followed);
        let problem = match robot_index {
            _ if followed == name => Some("a joint cannot follow itself".to_string()),
            None if doc.joints.iter().any(|j| j.name == *followed) => Some(format!(
                "`{followed}` is not a moving joint of the robot (it is fixed, or cut off by \
                 `tip` or `tips`)"
            )),
            None => Some(format!("the file has no joint `{followed}`")),
            Some(j) if doc.joints[urdf_joints[j]].mimic.is_some() => Some(format!(
                "`{followed}` is a mimic joint itself: a mimic joint follows a joint that is not"
            )),
            Some(j) if is_prismatic(doc, urdf_joints[j]) != is_prismatic(doc, u) => Some(format!(
                "`{name}` and `{followed}` are not of the same kind (revolute or prismatic): a \
                 mimic joint follows a joint of its own kind"
            )),
            Some(_) => None,
        };
        match (problem, robot_index) {
            (Some(p), _) => errors.push(error(mimic.at, format!("{prefix}: {p}"))),
            (None, Some(j)) => {
                joints[i].mimic = Some(Mimic {
                    joint: j,
                    multiplier: mimic.multiplier.clone(),
                    offset: mimic.offset.clone(),
                });
            }
            (None, None) => {}
        }
    }
    errors
}

fn is_prismatic(doc: &Description, joint: usize) -> bool {
    doc.joints[joint].kind == Kind::Prismatic
}
