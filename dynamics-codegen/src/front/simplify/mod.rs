//! `simplify(...)` in the attribute or `[simplify]` in a description file, resolved for the
//! robot once it is lowered: `given` reads and resolves the keys, this file picks the one
//! source and the defaults (a URDF's `<limit>`s). The derive and the command-line tool resolve
//! a file's request here, the same way ([`FileRequest::resolve`]).

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod given;

use given::{default_joint, Defaults, Given};

use super::errors::Errors;
use super::sources::{prefix, At};
use super::urdf::Limit;
use crate::model::{Robot, Simplification};
use proc_macro2::Span;
use syn::LitStr;

/// What a file gives `simplify(...)`: its own `[simplify]` (a description file's), and a
/// URDF's joint limits (the default envelope, and the rated torques of `tolerance_percent`).
pub struct FileRequest {
    /// The `[simplify]` table, its keys at their lines and columns.
    pub given: Option<Given<At>>,
    /// A URDF's `<limit>`s, one per joint of the robot.
    pub limits: Option<Vec<Limit>>,
    /// The file's path as written, for the messages.
    pub path: String,
}

/// A mistake in a request: in the file (`path:line:col: simplify: ...`), or in the values
/// given beside it (`simplify: ...`, the command line's options).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RequestError {
    /// Whether the file's table makes it.
    pub in_file: bool,
    /// The file's path, as given.
    pub path: String,
    /// Its line and column, where the file's table makes it.
    pub at: Option<At>,
    /// What is wrong (`simplify: ...`), without the place.
    pub problem: String,
}

/// `path:line:col: simplify: ...` for the file's mistake, `simplify: ...` for the caller's.
impl std::fmt::Display for RequestError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.in_file {
            f.write_str(&prefix(&self.path, self.at.as_ref()))?;
        }
        f.write_str(&self.problem)
    }
}

impl FileRequest {
    /// The request for `robot`: the file's `[simplify]` with each key of `overrides` (a
    /// key of `simplify(...)` and its values, one for every joint or one per joint) in place
    /// of the file's (`tolerance` in place of `rated` and `tolerance_percent` too, and
    /// either of these in place of `tolerance`); the
    /// defaults of the keys neither gives from the URDF's `<limit>`s, else from the joints'
    /// kinds. `None` where neither asks.
    ///
    /// # Errors
    /// Every mistake, each placed where it was made.
    pub fn resolve(
        &self,
        robot: &Robot,
        overrides: &[(&'static str, Vec<f64>)],
    ) -> Result<Option<Simplification>, Vec<RequestError>> {
        let mut merged: Given<Option<At>> = match &self.given {
            Some(given) => Given {
                at: Some(given.at),
                keys: given
                    .keys
                    .iter()
                    .map(|(key, values, at)| (*key, values.clone(), Some(*at)))
                    .collect(),
            },
            None if overrides.is_empty() => return Ok(None),
            None => Given {
                at: None,
                keys: Vec::new(),
            },
        };
        for (key, values) in overrides {
            // A tolerance given one way replaces the file's given the other.
            let replaced: &[&str] = match *key {
                "tolerance" => &["rated", "tolerance_percent"],
                "rated" | "tolerance_percent" => &["tolerance"],
                _ => &[],
            };
            merged
                .keys
                .retain(|(k, _, _)| k != key && !replaced.contains(k));
            merged.keys.push((*key, values.clone(), None));
        }
        let limits = self.limits.as_deref().unwrap_or_default();
        merged
            .resolve(&defaults(robot, limits))
            .map(Some)
            .map_err(|problems| {
                let placed = problems.into_iter().map(|(at, message)| RequestError {
                    in_file: at.is_some(),
                    path: self.path.clone(),
                    at,
                    problem: format!("simplify: {message}"),
                });
                placed.collect()
            })
    }
}

/// What a named file gives `simplify(...)`, and `at` the string naming it.
pub(super) struct FromFile<'a> {
    pub request: FileRequest,
    pub at: &'a LitStr,
}

/// What a request for `robot` takes where it does not say, per coordinate (every joint but
/// the mimic ones, which follow theirs): a URDF's `<limit>`s (range, speed; the efforts as
/// rated torques where every joint has one, a coordinate's its own joint's), else the joints'
/// kinds'.
fn defaults(robot: &Robot, limits: &[Limit]) -> Defaults {
    let coordinates = robot.coordinates();
    let joints = coordinates
        .iter()
        .map(|&i| {
            let mut e = default_joint(robot.joints[i].kind);
            if let Some(limit) = limits.get(i) {
                e.lower = limit.lower.unwrap_or(e.lower);
                e.upper = limit.upper.unwrap_or(e.upper);
                e.speed = limit.velocity.unwrap_or(e.speed);
            }
            e
        })
        .collect();
    let rated = (limits.len() == robot.joints.len())
        .then(|| {
            let efforts = coordinates
                .iter()
                .map(|&i| limits[i].effort.filter(|e| *e >= 0.0));
            efforts.collect::<Option<Vec<f64>>>()
        })
        .flatten();
    Defaults {
        joints,
        rated,
        coordinates: robot.has_mimics(),
    }
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
    let file_given = file.and_then(|f| Some((f.request.given.as_ref()?, f)));
    match (attr, file_given) {
        (Some(given), Some((_, f))) => {
            let message = format!(
                "`simplify` is given in `{}` too: give it in one place",
                f.request.path
            );
            errors.push(given.at, message);
            None
        }
        (Some(given), None) => {
            let limits = file.and_then(|f| f.request.limits.as_deref());
            given
                .resolve(&defaults(robot, limits.unwrap_or_default()))
                .map_err(|problems| {
                    for (at, message) in problems {
                        errors.push(at, message);
                    }
                })
                .ok()
        }
        (None, Some((_, f))) => f
            .request
            .resolve(robot, &[])
            .map_err(|problems| {
                for problem in problems {
                    errors.push(f.at.span(), problem.to_string());
                }
            })
            .ok()
            .flatten(),
        (None, None) => None,
    }
}
