//! Joints given in a description file URDF style, `origin = { xyz = [..], rpy = [..] }` and
//! `axis = [..]` in place of `theta`, `d`, `a`, `alpha`: read into [`AxisFrame`]s, then lowered
//! to the robot's own modified D-H table by [`lower_frames`], each problem at its joint's key.

use super::schema::{Deferred, FileJoint, FileValue};
use crate::model::{lower_frames, AxisFrame, Placement, Robot, Value};

impl FileJoint {
    /// Whether the joint is given by `origin` or `axis`.
    pub(super) fn has_frame(&self) -> bool {
        self.origin.is_some() || self.axis.is_some()
    }
}

/// Joint `joint`'s frame, where the file's joints are given by `origin` and `axis`
/// (`frames_given`); a D-H key in such a file is an error at its position.
pub(super) fn frame(
    joint: usize,
    j: &FileJoint,
    frames_given: bool,
    deferred: &mut Vec<Deferred>,
) -> Option<AxisFrame> {
    if !frames_given {
        return None;
    }
    let dh_keys = [
        ("theta", &j.theta),
        ("d", &j.d),
        ("a", &j.a),
        ("alpha", &j.alpha),
    ];
    if let Some((key, _)) = dh_keys.iter().find(|(_, v)| v.is_some()) {
        let message = if j.has_frame() {
            format!(
                "`{key}` cannot be combined with `origin` and `axis`: give the joint either by \
                 its D-H parameters or by its placement and axis"
            )
        } else {
            format!(
                "`{key}` is a D-H parameter, but the file's other joints are given by `origin` \
                 and `axis`: give every joint the same way"
            )
        };
        deferred.push((joint, key, message));
    }
    let three = |v: Option<&[FileValue; 3]>| -> [Value; 3] {
        v.map_or_else(Default::default, |v| v.each_ref().map(|x| x.0.clone()))
    };
    let origin = j.origin.as_ref();
    Some(AxisFrame {
        origin: Placement {
            xyz: three(origin.and_then(|o| o.xyz.as_ref())),
            rpy: three(origin.and_then(|o| o.rpy.as_ref())),
        },
        axis: j.axis.as_ref().map_or_else(
            || [Value::zero(), Value::zero(), Value::one()],
            |a| a.each_ref().map(|x| x.0.clone()),
        ),
    })
}

/// Lowers the robot, each problem deferred to its joint's `axis` or `origin`.
pub(super) fn lower(robot: &mut Robot, deferred: &mut Vec<Deferred>) {
    if let Err(problems) = lower_frames(robot) {
        deferred.extend(problems.into_iter().map(|p| {
            let key = if p.concerns_axis() { "axis" } else { "origin" };
            (p.joint, key, p.message)
        }));
    }
}
