//! The free flyer of `base = floating`: its body read from the URDF the robot came from (its
//! root link and every link fixed to it), from a description file's `[floating]` table, or
//! from the attribute's `base = floating(mass = .., com = [..], inertia = [..])` beside a D-H
//! table or `joints = [..]`, in the base frame (frame 0) as a link's; its gravity, in the
//! world frame, from `gravity = [..]` (the URDF's default `[0, 0, −9.81]`). Every key or family
//! the floating base does not support yet is refused on its token (`derivatives = true`,
//! `regressor = true` and `base_parameters = true` are supported, as
//! `FloatingDynamicsDerivatives`, `FloatingDynamicsRegressor`,
//! `FloatingDynamicsBaseParameters`), so that no robot gets methods that would be wrong on a
//! flying base.

use super::attrs::Attrs;
use super::errors::Errors;
use super::fields::Field;
use super::urdf;
use crate::method::Family;
use crate::model::{FreeFlyer, Link, Robot};

/// What the input gives beside the attributes.
pub(super) struct Given<'a> {
    /// The description file's absolute path (a URDF's is read again for its root link).
    pub tracked_file: Option<&'a str>,
    /// A description file's `[floating]` body, with the file's gravity as written.
    pub file_body: Option<FreeFlyer>,
    /// The struct's fields, which values may name.
    pub fields: &'a [Field],
}

/// Where the floating body comes from.
enum Body {
    /// The URDF's root link (or the link named) and the links fixed to it.
    Urdf,
    /// The attribute's `floating(mass = ..)`.
    Attribute(Link),
    /// A description file's `[floating]`, with its gravity.
    File(FreeFlyer),
}

/// The free flyer the attributes ask for, if any and if it can be read; every problem in
/// `errors`. `robot` is the robot the input describes, if it could be read.
pub(super) fn free_flyer(
    attrs: &Attrs,
    given: Given,
    robot: Option<&Robot>,
    errors: &mut Errors,
) -> Option<FreeFlyer> {
    let Some(floating) = attrs.floating.as_ref() else {
        if let Some(contacts) = &attrs.contacts {
            errors.push(contacts.span(), "`contacts` are a floating base's: add `base = floating` (a fixed base's contact is its base)");
        }
        if let (Some(file), Some(_)) = (&attrs.file, &given.file_body) {
            errors.push(file.span(), "the file's `[floating]` table is the body of a robot on a floating base: add `base = floating` (or remove the table)");
        }
        return None;
    };
    let span = floating.span;
    let before = errors.len();
    let body = body(attrs, &given, errors);
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
        errors.push(span, format!("`{} = true` is not supported on a floating base yet: `base = floating` gives M, h, τ, g and the forward dynamics (`FloatingDynamics`), and their first derivatives, regressor and base parameters with `derivatives = true`, `regressor = true`, `base_parameters = true`", family.name()));
    }
    if attrs.simplify.is_some() {
        errors.push(span, "`simplify(..)` is not supported on a floating base yet: `base = floating` gives M, h, τ, g and the forward dynamics (`FloatingDynamics`), and their first derivatives with `derivatives = true`");
    }
    // Without a robot, the description's own errors are told already.
    let robot = robot?;
    robot_problems(robot, span, errors);
    joint_terms_with_families(attrs, robot, span, errors);
    if errors.len() > before {
        return None;
    }
    match body? {
        Body::Urdf => urdf_flyer(attrs, given.tracked_file?, span, errors),
        Body::File(flyer) => Some(flyer),
        Body::Attribute(body) => Some(FreeFlyer {
            // Frame 0's link: a table's or a list's base has no name of its own.
            link: "base".to_string(),
            body,
            // As written: the robot's own is turned into its frame 0 when joints given by
            // frames are lowered. Its absence is told with the robot's.
            gravity: std::array::from_fn(|i| {
                let given = attrs.gravity.as_ref().map(|g| g[i].value.clone());
                given.unwrap_or_else(|| robot.gravity[i].clone())
            }),
        }),
    }
}

/// Where the body comes from, or `None` with an error where the input does not give it or
/// gives it twice.
fn body(attrs: &Attrs, given: &Given, errors: &mut Errors) -> Option<Body> {
    let floating = attrs.floating.as_ref()?;
    let in_attribute = floating.body(given.fields, errors);
    let at = floating.body_span().unwrap_or(floating.span);
    if attrs.urdf.is_some() {
        if in_attribute.is_some() {
            errors.push(at, "the URDF gives the floating body (its root link, or the link `floating(\"trunk\")` names): remove `mass`, `com` and `inertia` here");
            return None;
        }
        return Some(Body::Urdf);
    }
    if let Some(link) = &floating.link {
        errors.push(link.span(), "`floating(\"link\")` names a URDF's link: without a URDF, give the floating body as `base = floating(mass = .., com = [..], inertia = [..])`");
        return None;
    }
    match (in_attribute, given.file_body.clone(), &attrs.file) {
        (Some(_), _, Some(file)) => {
            errors.push(at, format!("a description file gives the floating body in its `[floating]` table: remove `mass`, `com` and `inertia` here (file `{}`)", file.value()));
            None
        }
        (None, None, Some(file)) => {
            errors.push(file.span(), "`base = floating`: the file has no `[floating]` table, the floating body (`mass`, `com`, `inertia` in the base frame, as a joint's)");
            None
        }
        (None, Some(flyer), Some(_)) => Some(Body::File(flyer)),
        (Some(body), _, None) => Some(Body::Attribute(body)),
        (None, _, None) => {
            errors.push(floating.span, "`base = floating` without a URDF needs the floating body: `base = floating(mass = .., com = [..], inertia = [..])`, in the base frame (frame 0), as a `link(..)`");
            None
        }
    }
}

/// The free flyer of the URDF at `path`: its root link (or the link named) and the links fixed
/// to it; gravity `gravity = [..]` or `[0, 0, −9.81]`.
fn urdf_flyer(
    attrs: &Attrs,
    path: &str,
    span: proc_macro2::Span,
    errors: &mut Errors,
) -> Option<FreeFlyer> {
    let text = std::fs::read_to_string(path).ok()?;
    let link = attrs
        .floating
        .as_ref()
        .and_then(|f| f.link.as_ref())
        .map(syn::LitStr::value);
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

/// What a floating base's equations leave out, refused: springs.
fn robot_problems(robot: &Robot, span: proc_macro2::Span, errors: &mut Errors) {
    for message in unsupported(robot) {
        errors.push(span, message);
    }
}

/// What of `robot` a floating base does not support yet, one message each: joint springs.
/// (Joint friction and actuator inertia are modelled: in `τ`, the forward dynamics and `M`'s
/// diagonal; mimic joints reduce every output to the coordinates, `trace/floating_mimic.rs`.)
#[must_use]
pub fn unsupported(robot: &Robot) -> Vec<String> {
    let mut found = Vec::new();
    for (i, joint) in robot.joints.iter().enumerate() {
        if joint.link.spring.is_some() {
            found.push(format!("joint {}: springs are not supported on a floating base yet (Pinocchio's free flyer has none)", i + 1));
        }
    }
    found
}

/// Whether a joint of `robot` has friction or actuator inertia that is not zero.
fn has_joint_terms(robot: &Robot) -> bool {
    robot.joints.iter().any(|joint| {
        let link = &joint.link;
        let friction = link
            .friction
            .iter()
            .flat_map(crate::model::Friction::values);
        friction
            .chain([&link.actuator_inertia])
            .any(|v| !v.is_zero())
    })
}

/// The floating base's regressor and base parameters have no columns for joint friction and
/// actuator inertia yet: refused beside them.
fn joint_terms_with_families(
    attrs: &Attrs,
    robot: &Robot,
    span: proc_macro2::Span,
    errors: &mut Errors,
) {
    let asked = attrs.families.iter().filter(|(_, &asked)| asked);
    for message in asked.filter_map(|(&family, _)| joint_terms_refusal(robot, family)) {
        errors.push(span, message);
    }
}

/// Why `family` (an opt-in family, by its fixed base's name or its floating twin) cannot be
/// traced beside the joint friction or actuator inertia of `robot` on a floating base, if it
/// cannot: the regressor and base parameters have no columns for them yet. (The derivatives
/// model them: `∂τ/∂v` has the viscous coefficients on its joints' diagonal, `M` the actuator
/// inertia.)
/// Mimic joints likewise: the regressor's columns are not projected onto the coordinates on a
/// floating base yet.
#[must_use]
pub fn joint_terms_refusal(robot: &Robot, family: Family) -> Option<String> {
    let floating = family.on_floating_base()?;
    if floating != Family::FloatingDerivatives && robot.has_mimics() {
        return Some(format!("`{} = true` is not supported on a floating base with mimic joints yet: `base = floating` reduces M, h, τ, g, the forward dynamics, the kinematics, the contacts and the first derivatives to the coordinates only", family.name()));
    }
    if floating == Family::FloatingDerivatives || !has_joint_terms(robot) {
        return None;
    }
    Some(format!("`{} = true` is not supported on a floating base with joint friction or actuator inertia yet (a joint's `<dynamics damping friction>`, `friction`, `actuator_inertia`): `base = floating` models them in M, τ, the forward dynamics and their derivatives only", family.name()))
}
