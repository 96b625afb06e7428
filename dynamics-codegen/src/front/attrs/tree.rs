//! Trees in the attribute: a joint's antecedent, `parent = 2` or `parent = "palm"` in
//! `joints = [revolute(..), ..]` (0 is the base; joints may have a `name`), and the antecedent
//! column of a modified D-H table, `[θ, d, a, α, antecedent, γ, b]`. A parent must come
//! earlier (so the joints make no cycle); each mistake is an error on its token.

use crate::front::parent::{resolve, ParentRef};
use crate::model::{Branch, Joint, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::parse::ParseStream;

/// A joint's `parent`: an earlier joint's 1-based number (0: the base) or name, with its span.
pub(super) enum ParentAttr {
    Number(u64, Span),
    Name(String, Span),
}

impl ParentAttr {
    pub(super) fn span(&self) -> Span {
        match self {
            ParentAttr::Number(_, span) | ParentAttr::Name(_, span) => *span,
        }
    }
}

/// `parent = 2` or `parent = "palm"`.
pub(super) fn parse_parent(input: ParseStream) -> syn::Result<ParentAttr> {
    match input.parse::<syn::Lit>() {
        Ok(syn::Lit::Int(n)) => Ok(ParentAttr::Number(n.base10_parse()?, n.span())),
        Ok(syn::Lit::Str(s)) => Ok(ParentAttr::Name(s.value(), s.span())),
        Ok(other) => Err(syn::Error::new(other.span(), PARENT_USAGE)),
        Err(e) => Err(syn::Error::new(e.span(), PARENT_USAGE)),
    }
}

const PARENT_USAGE: &str = "expected an earlier joint's number or name: `parent = 1` (the \
     first joint), `parent = \"palm\"`, or `parent = 0` (the base)";

/// Joint `n`'s (1-based) antecedent from its parent: an earlier joint (0-based), or `None` for
/// the base; `count` joints, `names` their names. Messages call the joints `joint`, or `row`
/// in a D-H table (`rows`), and the parent its antecedent there.
pub(super) fn antecedent(
    n: usize,
    parent: &ParentAttr,
    count: usize,
    names: &BTreeMap<&str, usize>,
    rows: bool,
) -> Result<Option<usize>, String> {
    let written = match parent {
        ParentAttr::Number(k, _) => ParentRef::Number(*k),
        ParentAttr::Name(name, _) => ParentRef::Name(name),
    };
    resolve(n - 1, written, count, names).map_err(|message| {
        let message = format!("joint {n}: {message}");
        if rows {
            message
                .replace("parent joint", "antecedent row")
                .replace("a parent", "an antecedent")
                .replace("parent", "antecedent")
                .replace("joint", "row")
                .replace("are given", "rows")
        } else {
            message
        }
    })
}

/// The joints' branches made whole: where some joint has one, every other hangs from the joint
/// before; where they make a chain (each joint's antecedent the one before, γ = b = 0), none.
pub(super) fn settle(joints: &mut [Joint]) {
    if joints.iter().all(|j| j.branch.is_none()) {
        return;
    }
    for (i, joint) in joints.iter_mut().enumerate() {
        joint.branch.get_or_insert_with(|| Branch {
            parent: i.checked_sub(1),
            gamma: Value::zero(),
            b: Value::zero(),
        });
    }
    let serial = joints.iter().enumerate().all(|(i, j)| {
        j.branch
            .as_ref()
            .is_some_and(|b| b.parent == i.checked_sub(1) && b.gamma.is_zero() && b.b.is_zero())
    });
    if serial {
        for joint in joints {
            joint.branch = None;
        }
    }
}
