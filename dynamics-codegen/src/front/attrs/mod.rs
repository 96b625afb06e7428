//! The attributes as input: `#[dynamics(gravity = [..], dh = [..], link(..), ...)]` (or
//! `joints = [..]` in place of `dh`) lowered to a [`Robot`] with the tokens of each value.
//!
//! The steps, one file each, each using only those before it: `keys` names every key once;
//! `entry` reads the value after a key; `friction`, `link` and `joints` read
//! `friction = (..)`, `link(..)` and `joints = [..]`; `parse` reads every key of the attribute
//! into [`Attrs`], still as tokens; `reader` turns values into model values, checked where they
//! are written, and a `link(..)` into a [`crate::model::Link`]; `dh` and `frames` build the
//! joints of a D-H table or of a joint list, the latter then lowered to its own D-H table. The physical checks of the links
//! are not made here: [`tell`] places their problems on these tokens afterwards.

mod dh;
mod entry;
mod floating;
mod frames;
mod friction;
mod joints;
mod keys;
mod link;
mod mimic;
mod parse;
mod reader;
mod simplify;
mod tree;

pub use keys::attribute_words;
pub(super) use parse::{parse_attrs, Attrs, Source};

use super::errors::Errors;
use super::fields::Field;
use super::sources::{Lowered, Sources, Tokens};
use crate::check::{Problem, MAX_JOINTS, MAX_TREE_JOINTS};
use crate::model::{Convention, Pose, Robot};
use proc_macro2::Span;
use reader::Reader;

/// The robot the attributes describe, with the tokens of each value, and how its joint list
/// counts (for the joint-count problem); its errors go to `errors`.
pub(super) fn lower(
    attrs: &Attrs,
    input: &syn::DeriveInput,
    fields: &[Field],
    errors: &mut Errors,
) -> (Lowered<Tokens>, fn(usize) -> String) {
    let span = input.ident.span();
    let mut reader = Reader::new(fields, errors);
    let gravity = match &attrs.gravity {
        Some(g) => reader.values(g),
        None => {
            reader.errors.push(span, "missing `gravity = [gx, gy, gz]`: the gravity acceleration in the base frame, e.g. `[0, 0, -9.81]`");
            Default::default()
        }
    };
    let counted: fn(usize) -> String = match &attrs.dh {
        Some(_) => dh::counted,
        None => frames::counted,
    };
    let joints = match (&attrs.dh, &attrs.joints) {
        (Some(rows), _) => dh::joints(&mut reader, rows, attrs, span),
        (None, Some(list)) => frames::joints(&mut reader, list, attrs, span),
        (None, None) => {
            reader.errors.push(
                span,
                "missing `dh = [[θ, d, a, α], ...]`: the D-H table, one row per joint (or \
                 `joints = [revolute(xyz = [..], rpy = [..], axis = [..]), ...]`)",
            );
            Vec::new()
        }
    };
    let tool = reader.tool(attrs.tool.as_ref());
    let mut robot = Robot {
        name: input.ident.to_string(),
        convention: attrs.convention.map_or(Convention::Standard, |c| c.0),
        gravity,
        joints,
        base: Pose::identity(),
        tool,
        tips: Vec::new(),
    };
    if let (None, Some((list, _))) = (&attrs.dh, &attrs.joints) {
        robot.convention = Convention::Standard;
        frames::lower(&mut robot, list, &mut reader);
    }
    let lowered = Lowered {
        robot,
        check_inertia: reader.check_inertia,
        sources: reader.sources,
        simplify: None,
        // `floating(mass = ..)`'s body is read beside the robot (`FloatingAttr::body`).
        floating: None,
    };
    (lowered, counted)
}

/// Where a problem of the checks goes in the attribute, and what it says there: on the value
/// it concerns (the `link` keyword where the link does not give it), `link 2: ...`; too many
/// joints on the first row or entry past the limit, said as `counted` says the count.
pub(super) fn tell(
    sources: &Sources<Tokens>,
    counted: fn(usize) -> String,
    problem: &Problem,
) -> (Tokens, String) {
    let call_site = (Span::call_site(), Span::call_site());
    let message = match problem {
        Problem::TooManyJoints { count } => format!(
            "{}; at most {MAX_JOINTS} joints are supported (the generated code grows as n³)",
            counted(*count)
        ),
        Problem::TooManyInTree { count } => format!(
            "{}; at most {MAX_TREE_JOINTS} joints are supported in a tree (and {MAX_JOINTS} \
             along any path from the base)",
            counted(*count)
        ),
        Problem::PathTooLong { .. } => problem.to_string(),
        Problem::Link { joint, problem } => format!("link {}: {}", joint + 1, problem.message),
        Problem::Branch { joint, problem } => format!("joint {}: {}", joint + 1, problem.message),
    };
    let fallback = match problem {
        Problem::Link { joint, .. }
        | Problem::Branch { joint, .. }
        | Problem::PathTooLong { joint } => sources.get(*joint, "link"),
        Problem::TooManyJoints { .. } | Problem::TooManyInTree { .. } => None,
    };
    let at = sources.place(problem).or(fallback).copied();
    (at.unwrap_or(call_site), message)
}
