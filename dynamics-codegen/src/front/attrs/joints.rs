//! The value of `joints = [...]`: joints given URDF style, base to tip, each
//! `revolute(xyz = [..], rpy = [..], axis = [..])` or `prismatic(..)`, read into [`JointAttr`]s
//! with their spans. `xyz` and `rpy` default to zero, `axis` to `[0, 0, 1]`; in a tree,
//! `parent` (default: the joint before) and `name`; `mimic = (..)` for a joint that follows
//! another.

use super::entry::{skip_entry, string, values, Entry};
use super::keys::{JointKey, JointType};
use super::mimic::{parse_mimic, MimicAttr};
use super::tree::{parse_parent, ParentAttr};
use crate::front::errors::{unknown_key, Errors};
use crate::front::value::Spanned;
use crate::model::JointKind;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::{bracketed, parenthesized, Ident, LitStr, Token};

/// One entry of `joints = [...]`.
pub(super) struct JointAttr {
    /// The `revolute` or `prismatic` keyword.
    pub span: Span,
    /// The closing parenthesis of its keys.
    pub end: Span,
    pub kind: JointKind,
    pub xyz: Option<[Spanned; 3]>,
    pub rpy: Option<[Spanned; 3]>,
    /// The three values and the span of their brackets.
    pub axis: Option<([Spanned; 3], Span)>,
    /// In a tree: the joint it hangs from, and its own name.
    pub parent: Option<ParentAttr>,
    pub name: Option<LitStr>,
    /// The joint it follows, if it is a mimic joint.
    pub mimic: Option<MimicAttr>,
}

/// What the keys of `revolute(...)` are called in messages.
const JOINT_ATTRIBUTE: &str = "joint attribute";

/// Parses `[revolute(..), prismatic(..), ...]`, with the span of its brackets.
pub(super) fn parse_joints(
    input: ParseStream,
    errors: &mut Errors,
) -> syn::Result<(Vec<JointAttr>, Span)> {
    if !input.peek(syn::token::Bracket) {
        return Err(input.error(
            "expected the joints in brackets, base to tip: \
             `joints = [revolute(xyz = [..], rpy = [..], axis = [..]), ...]`",
        ));
    }
    let content;
    let bracket = bracketed!(content in input);
    let mut joints = Vec::new();
    while !content.is_empty() {
        let ident: Ident = content.parse()?;
        let Some(kind) = JointType::find(&ident) else {
            return Err(syn::Error::new(
                ident.span(),
                unknown_key(&ident, "joint type", JointType::NAMES),
            ));
        };
        if !content.peek(syn::token::Paren) {
            return Err(content.error(format!(
                "expected `{ident}(xyz = [..], rpy = [..], axis = [..])`"
            )));
        }
        let keys;
        let paren = parenthesized!(keys in content);
        let mut joint = JointAttr {
            span: ident.span(),
            end: paren.span.close(),
            kind: match kind {
                JointType::Revolute => JointKind::Revolute,
                JointType::Prismatic => JointKind::Prismatic,
            },
            xyz: None,
            rpy: None,
            axis: None,
            parent: None,
            name: None,
            mimic: None,
        };
        parse_joint_keys(&keys, &mut joint, errors)?;
        joints.push(joint);
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok((joints, bracket.span.join()))
}

/// Parses the keys of one `revolute(...)` or `prismatic(...)` into `joint`.
fn parse_joint_keys(
    input: ParseStream,
    joint: &mut JointAttr,
    errors: &mut Errors,
) -> syn::Result<()> {
    while !input.is_empty() {
        let ident: Ident = input.parse()?;
        let Some(key) = JointKey::find(&ident) else {
            errors.push(
                ident.span(),
                unknown_key(&ident, JOINT_ATTRIBUTE, JointKey::NAMES),
            );
            skip_entry(input)?;
            if !input.is_empty() {
                input.parse::<Token![,]>()?;
            }
            continue;
        };
        input.parse::<Token![=]>()?;
        let mut entry = Entry {
            ident: &ident,
            what: JOINT_ATTRIBUTE,
            errors,
        };
        match key {
            JointKey::Xyz => {
                let (xyz, _) = values::<3>(input, "`xyz = [x, y, z]`")?;
                entry.keep_first(&mut joint.xyz, xyz);
            }
            JointKey::Rpy => {
                let (rpy, _) = values::<3>(input, "`rpy = [roll, pitch, yaw]`")?;
                entry.keep_first(&mut joint.rpy, rpy);
            }
            JointKey::Axis => {
                let axis = values::<3>(input, "`axis = [x, y, z]`")?;
                entry.keep_first(&mut joint.axis, axis);
            }
            JointKey::Parent => entry.keep_first(&mut joint.parent, parse_parent(input)?),
            JointKey::Mimic => {
                let mimic = parse_mimic(input, entry.errors)?;
                entry.keep_first(&mut joint.mimic, mimic);
            }
            JointKey::Name => {
                entry.keep_first(&mut joint.name, string(input, "`name = \"palm\"`")?)
            }
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(())
}
