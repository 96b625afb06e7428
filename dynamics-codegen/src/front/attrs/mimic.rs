//! `mimic = (joint = 2, multiplier = -1, offset = 0.1)` in a `revolute(..)` or `prismatic(..)`
//! of `joints = [..]`: the joint follows `q = multiplier · q_joint + offset` (URDF's `<mimic>`)
//! and is not a coordinate of the robot. `joint` is written as `parent` is, an earlier or later
//! joint's 1-based number or its `name`; `multiplier` defaults to 1 and `offset` to 0.

use super::tree::{parse_parent, ParentAttr};
use crate::front::errors::{unknown_key, Errors};
use crate::front::value::Spanned;
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::parse::ParseStream;
use syn::{parenthesized, Ident, Token};

/// The keys of `mimic = (...)`.
const KEYS: &[&str] = &["joint", "multiplier", "offset"];

/// The values of `mimic = (...)`, with the span of the parentheses.
pub(super) struct MimicAttr {
    pub joint: Option<ParentAttr>,
    pub multiplier: Option<Spanned>,
    pub offset: Option<Spanned>,
    pub span: Span,
}

/// Parses `(joint = .., multiplier = .., offset = ..)` after `mimic =`; an unknown or repeated
/// key is an error and parsing goes on.
pub(super) fn parse_mimic(input: ParseStream, errors: &mut Errors) -> syn::Result<MimicAttr> {
    if !input.peek(syn::token::Paren) {
        return Err(input.error(
            "expected `mimic = (joint = 2, multiplier = 1, offset = 0)`: the joint followed, by \
             number or name, then the optional multiplier and offset",
        ));
    }
    let content;
    let paren = parenthesized!(content in input);
    let mut mimic = MimicAttr {
        joint: None,
        multiplier: None,
        offset: None,
        span: paren.span.join(),
    };
    while !content.is_empty() {
        let ident: Ident = content.parse()?;
        content.parse::<Token![=]>()?;
        let given = match ident.to_string().as_str() {
            "joint" => {
                let joint =
                    parse_parent(&content).map_err(|e| syn::Error::new(e.span(), JOINT_USAGE))?;
                mimic.joint.replace(joint).is_some()
            }
            key => {
                let value: Spanned = content.parse()?;
                match key {
                    "multiplier" => mimic.multiplier.replace(value).is_some(),
                    "offset" => mimic.offset.replace(value).is_some(),
                    _ => {
                        errors.push(ident.span(), unknown_key(&ident, "mimic key", KEYS));
                        false
                    }
                }
            }
        };
        if given {
            errors.push(
                ident.span(),
                format!("duplicate mimic key `{ident}`: it is given earlier in this list"),
            );
        }
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    if mimic.joint.is_none() {
        errors.push(
            mimic.span,
            "`mimic` names no `joint`: `mimic = (joint = 2)` or `mimic = (joint = \"finger\")`",
        );
    }
    Ok(mimic)
}

const JOINT_USAGE: &str =
    "expected the joint followed, by number or name: `joint = 2` or `joint = \"finger\"`";

/// Joint `n`'s (1-based) followed joint (0-based), of `count` joints named `names`.
pub(super) fn followed(
    n: usize,
    joint: &ParentAttr,
    count: usize,
    names: &BTreeMap<&str, usize>,
) -> Result<usize, String> {
    let index = match joint {
        ParentAttr::Number(k, _) => match usize::try_from(*k) {
            Ok(k) if (1..=count).contains(&k) => k - 1,
            _ => {
                return Err(format!(
                    "joint {n}: mimic joint {k}: there is no joint {k} (joints are numbered 1 \
                     to {count})"
                ))
            }
        },
        ParentAttr::Name(name, _) => *names
            .get(name.as_str())
            .ok_or_else(|| format!("joint {n}: mimic joint `{name}`: no joint has that name"))?,
    };
    if index + 1 == n {
        return Err(format!("joint {n}: it cannot mimic itself"));
    }
    Ok(index)
}
