//! The robot built from `joints = [...]`: one joint per `revolute(..)` or `prismatic(..)` with
//! its `link(...)` (inertial parameters in link frame i, the joint frame), then lowered to the
//! robot's own modified D-H table by [`lower_frames`], whose problems go on the joint's tokens.

use super::angle::unitless_angle;
use super::attr::Attrs;
use super::attr_joints::JointAttr;
use super::from_attrs::{check_joint_count, JointList, Reader};
use crate::model::{lower_frames, AxisFrame, Convention, Joint, Placement, Pose, Robot, Value};
use proc_macro2::Span;

/// The robot of `joints = [...]` (the list and the span of its brackets), lowered where every
/// value was read without error.
pub(super) fn robot(
    attrs: &Attrs,
    (joints, list_span): &(Vec<JointAttr>, Span),
    input: &syn::DeriveInput,
    gravity: [Value; 3],
    reader: &mut Reader,
) -> Robot {
    let span = input.ident.span();
    let spans: Vec<Span> = joints.iter().map(|j| j.span).collect();
    let list = JointList {
        spans: &spans,
        span: *list_span,
        empty: "`joints` is empty: give one `revolute(..)` or `prismatic(..)` per joint",
        counted: |n| format!("{n} joints are given"),
    };
    check_joint_count(&list, &attrs.links, reader.errors);
    if let Some((_, at)) = attrs.convention {
        reader.errors.push(
            at,
            "`convention` applies to a D-H table: joints given by `joints = [..]` are lowered \
             to their own modified D-H table; remove `convention`",
        );
    }
    let built = joints
        .iter()
        .enumerate()
        .map(|(i, j)| joint(reader, i + 1, j, attrs, span))
        .collect();
    let mut robot = Robot {
        name: input.ident.to_string(),
        convention: Convention::Standard,
        gravity,
        joints: built,
        base: Pose::identity(),
        tool: super::from_attrs::tool(reader, attrs),
    };
    if reader.errors.is_empty() {
        if let Err(problems) = lower_frames(&mut robot) {
            for problem in problems {
                let j = &joints[problem.joint];
                let (start, end) = match (&j.axis, problem.concerns_axis()) {
                    (Some((_, brackets)), true) => (*brackets, *brackets),
                    _ => (j.span, j.end),
                };
                let message = format!("joint {}: {}", problem.joint + 1, problem.message);
                reader.errors.push_range(start, end, message);
            }
        }
    }
    robot
}

/// Joint `n` (1-based) as its entry gives it, with its `link(...)`.
fn joint(reader: &mut Reader, n: usize, j: &JointAttr, attrs: &Attrs, span: Span) -> Joint {
    let xyz = j
        .xyz
        .as_ref()
        .map_or_else(Default::default, |v| reader.values(v));
    let rpy = match &j.rpy {
        Some(angles) => {
            for angle in angles {
                if let Some((term, message)) = unitless_angle(&angle.unitless, false) {
                    reader.errors.push_range(term.span, term.end, message);
                }
            }
            reader.values(angles)
        }
        None => Default::default(),
    };
    let axis = match &j.axis {
        Some((v, _)) => reader.values(v),
        None => [Value::zero(), Value::zero(), Value::one()],
    };
    let link = reader.link(n, attrs.links.get(n - 1), attrs.check_inertia, span);
    let frame = AxisFrame {
        origin: Placement { xyz, rpy },
        axis,
    };
    Joint::framed(j.kind, frame, link)
}
