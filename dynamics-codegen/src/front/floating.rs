//! The free flyer of `base = floating`: its body read from the URDF the robot came from, its
//! gravity from `gravity = [..]` (in the world frame) or `[0, 0, −9.81]`; and every key or
//! family the floating base does not support yet refused on its token (`derivatives = true`
//! is, as `FloatingDynamicsDerivatives`), so that no robot gets methods that would be wrong
//! on a flying base.

use super::attrs::Attrs;
use super::errors::Errors;
use super::urdf;
use crate::model::{FreeFlyer, Robot};

/// The free flyer the attributes ask for, if any and if it can be read; every problem in
/// `errors`. `tracked_file` is the URDF's absolute path, `robot` its robot.
pub(super) fn free_flyer(
    attrs: &Attrs,
    tracked_file: Option<&str>,
    robot: Option<&Robot>,
    errors: &mut Errors,
) -> Option<FreeFlyer> {
    let floating = attrs.floating.as_ref()?;
    let span = floating.span;
    let before = errors.len();
    if attrs.urdf.is_none() {
        errors.push(
            span,
            "`base = floating` reads the robot from a URDF: give it with `urdf = \"robots/robot.urdf\"` (D-H tables, joint lists and description files on a floating base are not supported yet)",
        );
    }
    // `tips = [..]` names the frames of `FloatingKinematics`; a serial `tip` has no meaning
    // on a tree that flies.
    if let Some(at) = attrs.tip.as_ref().map(syn::LitStr::span) {
        errors.push(at, "`tip` is not supported on a floating base: name the frames with `tips = [\"FL_FOOT\", ..]` (`FloatingKinematics`)");
    }
    // A family with a floating base's twin (`derivatives`) is that family's.
    let asked = attrs
        .families
        .iter()
        .filter(|(family, &asked)| asked && family.on_floating_base().is_none());
    for (family, _) in asked {
        errors.push(span, format!("`{} = true` is not supported on a floating base yet: `base = floating` gives M, h, τ, g and the forward dynamics (`FloatingDynamics`), and their first derivatives with `derivatives = true`", family.name()));
    }
    if attrs.simplify.is_some() {
        errors.push(span, "`simplify(..)` is not supported on a floating base yet: `base = floating` gives M, h, τ, g and the forward dynamics (`FloatingDynamics`), and their first derivatives with `derivatives = true`");
    }
    // Without a robot, the URDF's own errors are told already.
    let robot = robot?;
    robot_problems(robot, span, errors);
    if errors.len() > before {
        return None;
    }
    let text = std::fs::read_to_string(tracked_file?).ok()?;
    let link = floating.link.as_ref().map(syn::LitStr::value);
    match urdf::free_flyer(&text, link.as_deref()) {
        Ok(mut flyer) => {
            if let Some(gravity) = &attrs.gravity {
                flyer.gravity = std::array::from_fn(|i| gravity[i].value.clone());
            }
            Some(flyer)
        }
        Err(found) => {
            for e in found {
                errors.push(span, format!("`base = floating`: {e}"));
            }
            None
        }
    }
}

/// What a floating base's equations leave out, refused: mimic joints, and joint terms that are
/// not zero (friction, actuator inertia, springs).
fn robot_problems(robot: &Robot, span: proc_macro2::Span, errors: &mut Errors) {
    if robot.has_mimics() {
        errors.push(
            span,
            "mimic joints are not supported on a floating base yet",
        );
    }
    for (i, joint) in robot.joints.iter().enumerate() {
        let link = &joint.link;
        let friction = link
            .friction
            .iter()
            .flat_map(crate::model::Friction::values);
        let nonzero = friction
            .chain([&link.actuator_inertia])
            .any(|v| !v.is_zero())
            || link.spring.is_some();
        if nonzero {
            errors.push(span, format!("joint {}: friction, actuator inertia and springs are not supported on a floating base yet (Pinocchio's free flyer has none): the joint's `<dynamics>` must be zero", i + 1));
        }
    }
}
