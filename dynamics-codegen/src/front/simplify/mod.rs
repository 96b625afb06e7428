//! `simplify(...)` in the attribute or `[simplify]` in a description file, resolved for the
//! robot once it is lowered: `given` reads and resolves the keys, this file picks the one
//! source and the defaults (a URDF's `<limit>`s).

pub(in crate::front) mod given;

use given::{default_joint, Given};

use super::errors::Errors;
use super::sources::At;
use super::urdf::Limit;
use crate::model::{JointEnvelope, Robot, Simplification};
use proc_macro2::Span;
use syn::LitStr;

/// What a named file gives `simplify(...)`: its own `[simplify]`, and a URDF's joint limits
/// (the default envelope); `at` the string naming the file at `path`.
pub(super) struct FromFile<'a> {
    pub given: Option<Given<At>>,
    pub limits: Option<Vec<Limit>>,
    pub at: &'a LitStr,
    pub path: String,
}

/// The request for `robot`: the attribute's `simplify(...)` or the file's `[simplify]` (not
/// both), its defaults from a URDF's `<limit>`s (range and speed) where it has them, else from
/// the joints' kinds; every mistake pushed to `errors` on its key (a file's on the string
/// naming it, with the line and column in the message).
pub(super) fn request(
    attr: Option<&Given<Span>>,
    file: Option<&FromFile>,
    robot: &Robot,
    errors: &mut Errors,
) -> Option<Simplification> {
    let limits = file.and_then(|f| f.limits.as_deref()).unwrap_or_default();
    let defaults: Vec<JointEnvelope> = robot
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let mut e = default_joint(j.kind);
            if let Some(limit) = limits.get(i) {
                e.lower = limit.lower.unwrap_or(e.lower);
                e.upper = limit.upper.unwrap_or(e.upper);
                e.speed = limit.velocity.unwrap_or(e.speed);
            }
            e
        })
        .collect();
    let from_file = file.and_then(|f| Some((f.given.as_ref()?, f)));
    match (attr, from_file) {
        (Some(given), Some((_, f))) => {
            let message = format!(
                "`simplify` is given in `{}` too: give it in one place",
                f.path
            );
            errors.push(given.at, message);
            None
        }
        (Some(given), None) => given
            .resolve(&defaults)
            .map_err(|problems| {
                for (at, message) in problems {
                    errors.push(at, message);
                }
            })
            .ok(),
        (None, Some((given, f))) => given
            .resolve(&defaults)
            .map_err(|problems| {
                for ((line, column), message) in problems {
                    errors.push(
                        f.at.span(),
                        format!("{}:{line}:{column}: simplify: {message}", f.path),
                    );
                }
            })
            .ok(),
        (None, None) => None,
    }
}
