//! The joints of `joints = [...]`: one per `revolute(..)` or `prismatic(..)` with its
//! `link(...)` (inertial parameters in link frame i, the joint frame), then lowered to the
//! robot's own modified D-H table by [`lower_frames`], whose problems go on the joint's tokens.

use super::joints::JointAttr;
use super::mimic;
use super::parse::Attrs;
use super::reader::{check_joint_count, JointList, Reader};
use super::tree::{self, ParentAttr};
use crate::front::angle::unitless_angle;
use crate::model::{lower_frames, AxisFrame, Branch, Joint, Mimic, Placement, Robot, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;

/// What the count errors call the list's entries.
pub(super) fn counted(n: usize) -> String {
    format!("{n} joints are given")
}

/// The joints of `joints = [...]` (the list and the span of its brackets), before lowering;
/// `span` is the derive's name.
pub(super) fn joints(
    reader: &mut Reader,
    (joints, list_span): &(Vec<JointAttr>, Span),
    attrs: &Attrs,
    span: Span,
) -> Vec<Joint> {
    let spans: Vec<Span> = joints.iter().map(|j| j.span).collect();
    let list = JointList {
        spans: &spans,
        span: *list_span,
        empty: "`joints` is empty: give one `revolute(..)` or `prismatic(..)` per joint",
        counted,
    };
    check_joint_count(&list, &attrs.links, reader.errors);
    if let Some((_, at)) = attrs.convention {
        reader.errors.push(
            at,
            "`convention` applies to a D-H table: joints given by `joints = [..]` are lowered \
             to their own modified D-H table; remove `convention`",
        );
    }
    let names = names(joints, reader);
    let names: BTreeMap<&str, usize> = names.iter().map(|(k, &i)| (k.as_str(), i)).collect();
    let mut model: Vec<Joint> = joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let mut joint = joint(reader, i + 1, j, attrs, span);
            let parent = j.parent.as_ref().map(|parent| {
                tree::antecedent(i + 1, parent, joints.len(), &names, false).unwrap_or_else(
                    |message| {
                        reader.errors.push(parent.span(), message);
                        i.checked_sub(1)
                    },
                )
            });
            joint.branch = parent.map(|parent| Branch {
                parent,
                gamma: Value::zero(),
                b: Value::zero(),
            });
            joint.mimic = j.mimic.as_ref().and_then(|m| {
                let followed = mimic::followed(i + 1, m.joint.as_ref()?, joints.len(), &names);
                let followed = followed.map_err(|message| {
                    let span = m.joint.as_ref().map_or(m.span, ParentAttr::span);
                    reader.errors.push(span, message);
                });
                Some(Mimic {
                    joint: followed.ok()?,
                    multiplier: m.multiplier.as_ref().map_or_else(
                        || Value::num(crate::symbolic::Number::ONE),
                        |v| reader.value(Some(v)),
                    ),
                    offset: reader.value(m.offset.as_ref()),
                })
            });
            joint
        })
        .collect();
    tree::settle(&mut model);
    model
}

/// Each named joint's index; a name given twice is an error on the second.
fn names(joints: &[JointAttr], reader: &mut Reader) -> BTreeMap<String, usize> {
    let mut names = BTreeMap::new();
    for (i, j) in joints.iter().enumerate() {
        let Some(name) = &j.name else { continue };
        if let Some(first) = names.get(&name.value()) {
            let message = format!(
                "joint {} is named `{}` too: give each joint its own name",
                first + 1,
                name.value()
            );
            reader.errors.push(name.span(), message);
        } else {
            names.insert(name.value(), i);
        }
    }
    names
}

/// Lowers `robot`, whose joints are those of `joints`, where every value was read without
/// error; each problem goes on its joint's axis or entry.
pub(super) fn lower(robot: &mut Robot, joints: &[JointAttr], reader: &mut Reader) {
    if !reader.errors.is_empty() {
        return;
    }
    if let Err(problems) = lower_frames(robot) {
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
    let link = reader.link((n, j.span), &attrs.links, attrs.check_inertia, span);
    let frame = AxisFrame {
        origin: Placement { xyz, rpy },
        axis,
    };
    Joint::framed(j.kind, frame, link)
}
