//! The derive's `urdf = "..."` (with `base = ".."`, `tip = ".."`): the chain of a URDF file
//! (found as `file = "..."` is, tracked for rebuilds) read into a robot by
//! [`super::load_urdf`], then checked as a description file is. Every error goes on the
//! `urdf = "..."` string, with the file's name, line and column in the message.

use super::attr::{Attrs, Source};
use super::errors::Errors;
use super::fields::{check_names, Field};
use super::from_file::{problems, read_relative};
use super::urdf::{load_urdf, Chain};
use crate::model::{mat_vec, transpose, Robot, Value};
use syn::LitStr;

/// Why `tool` is refused beside a URDF.
fn tool_hint(key: &str) -> &'static str {
    if key == "tool" {
        " (its `tip` link is the hand frame: choose the tip)"
    } else {
        ""
    }
}

/// The robot of the URDF file `urdf = "..."` names; `gravity = [..]` replaces its default
/// `[0, 0, −9.81]` (in the base link's frame).
pub(super) fn robot_from_urdf(
    urdf: &LitStr,
    attrs: &Attrs,
    fields: &[Field],
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<Robot> {
    let source = Source {
        key: "urdf",
        at: urdf,
        called: "the URDF file",
    };
    let keys = ["file", "dh", "joints", "link", "convention", "tool"];
    attrs.refuse_beside(&source, &keys, tool_hint, errors);
    let (relative, text) = read_relative(urdf, errors, tracked)?;
    let (base, tip) = (
        attrs.base.as_ref().map(LitStr::value),
        attrs.tip.as_ref().map(LitStr::value),
    );
    let chain = Chain {
        base: base.as_deref(),
        tip: tip.as_deref(),
    };
    let check_inertia = attrs.check_inertia.unwrap_or(true);
    let mut loaded = match load_urdf(&relative, &text, chain, check_inertia) {
        Ok(loaded) => loaded,
        Err(found) => {
            for e in found {
                let sep = if e.line.is_some() { "" } else { " " };
                errors.push(urdf.span(), format!("{relative}:{sep}{e}"));
            }
            return None;
        }
    };
    for message in problems(&loaded, &relative, check_inertia, fields) {
        errors.push(urdf.span(), message);
    }
    if let Some(gravity) = &attrs.gravity {
        for g in gravity {
            check_names(g, fields, errors);
        }
        // Given in the base link's frame; the lowered robot's gravity is in D-H frame 0.
        let given: [Value; 3] = std::array::from_fn(|i| gravity[i].value.clone());
        loaded.robot.gravity = mat_vec(&transpose(&loaded.robot.base.rotation), &given);
    }
    Some(loaded.robot)
}

/// `base = ".."` and `tip = ".."` name links of a URDF file: an error on each without `urdf`.
pub(super) fn chain_without_urdf(attrs: &Attrs, errors: &mut Errors) {
    for (key, given) in [("base", &attrs.base), ("tip", &attrs.tip)] {
        if let Some(literal) = given {
            errors.push(
                literal.span(),
                format!("`{key}` names a link of a URDF file: give the file with `urdf = \"robots/arm.urdf\"`"),
            );
        }
    }
}
