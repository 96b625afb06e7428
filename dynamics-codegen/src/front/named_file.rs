//! The derive's `file = "..."` and `urdf = "..."` (with `base = ".."`, `tip = ".."`): the file
//! read (relative to the crate's `Cargo.toml`, else to the source file: `locate`; tracked for
//! rebuilds) and lowered by
//! [`super::file::load`] or [`super::urdf::load_urdf`], then checked against the struct: the
//! fields its values name must be floats of it. Every error goes on the string that names the
//! file, with the file's name, line and column in the message.

use super::errors::{Errors, Requested};
use super::fields::{check_names, field_error, Field};
use super::file;
use super::sources::{Loaded, Positions, Tokens};
use super::urdf::{joint_limits, load_urdf, Chain, Limit};
use super::value::Spanned;
use crate::check::Problem;
use crate::model::{mat_vec, transpose, Robot, Value};
use std::path::{Path, PathBuf};
use syn::LitStr;

/// A robot lowered from the file a string names, with the file's path as written.
pub(super) struct Named {
    pub loaded: Loaded,
    pub path: String,
    /// A URDF's joint limits (`<limit>`), the default envelope of `simplify(...)`.
    pub limits: Option<Vec<Limit>>,
}

/// Reads the description file `file` names; `tracked` is set to its absolute path, for
/// rebuilds. `check_inertia = false` on the derive turns off the inertia checks of every joint.
pub(super) fn robot_from_file(
    file: &LitStr,
    check_inertia: bool,
    fields: &[Field],
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<Named> {
    let (relative, text) = read_relative(file, errors, tracked)?;
    let loaded = match file::load(&relative, &text) {
        Ok(loaded) => loaded,
        Err(e) => {
            let sep = if e.line.is_some() { "" } else { " " };
            errors.push(file.span(), format!("{relative}:{sep}{e}"));
            return None;
        }
    };
    Some(named(file, loaded, relative, check_inertia, fields, errors))
}

/// The joints asked of a URDF file, and the strings of the derive's `base`, `tip` and `tips`
/// where given: an error about the link one names goes on it.
pub(super) struct UrdfRequest<'a> {
    pub chain: Chain<'a>,
    pub base: Option<&'a LitStr>,
    pub tip: Option<&'a LitStr>,
    pub tips: &'a [LitStr],
}

impl UrdfRequest<'_> {
    /// The string `key` is, if given.
    fn get(&self, key: Requested) -> Option<&LitStr> {
        match key {
            Requested::Base => self.base,
            Requested::Tip => self.tip,
            Requested::Tips(i) => self.tips.get(i),
        }
    }
}

/// The robot of the URDF file `urdf = "..."` names, the joints `request` asks of it;
/// `gravity = [..]` replaces its default `[0, 0, −9.81]` (in the base link's frame).
pub(super) fn robot_from_urdf(
    urdf: &LitStr,
    request: &UrdfRequest<'_>,
    check_inertia: bool,
    gravity: Option<&[Spanned; 3]>,
    fields: &[Field],
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<Named> {
    let (relative, text) = read_relative(urdf, errors, tracked)?;
    let loaded = match load_urdf(&relative, &text, request.chain, check_inertia) {
        Ok(loaded) => loaded,
        Err(found) => {
            for e in found {
                let sep = if e.line.is_some() { "" } else { " " };
                let at = e.about.and_then(|key| request.get(key)).unwrap_or(urdf);
                errors.push(at.span(), format!("{relative}:{sep}{e}"));
            }
            return None;
        }
    };
    let limits = joint_limits(&text, request.chain).ok();
    let mut named = named(urdf, loaded, relative, check_inertia, fields, errors);
    named.limits = limits;
    if let Some(gravity) = gravity {
        for g in gravity {
            check_names(g, fields, errors);
        }
        // Given in the base link's frame; the lowered robot's gravity is in D-H frame 0.
        let robot = &mut named.loaded.robot;
        let given: [Value; 3] = std::array::from_fn(|i| gravity[i].value.clone());
        robot.gravity = mat_vec(&transpose(&robot.base.rotation), &given);
    }
    Some(named)
}

/// The robot `loaded` from the file `file` names (at `path`), its values checked against the
/// struct's `fields`; the derive's `check_inertia = false` turns off every joint's inertia
/// check.
fn named(
    file: &LitStr,
    mut loaded: Loaded,
    path: String,
    check_inertia: bool,
    fields: &[Field],
    errors: &mut Errors,
) -> Named {
    for message in value_problems(&loaded, &path, fields) {
        errors.push(file.span(), message);
    }
    for checked in &mut loaded.check_inertia {
        *checked &= check_inertia;
    }
    Named {
        loaded,
        path,
        limits: None,
    }
}

/// Where a problem of the checks goes: on the string `file` that names the file at `path`,
/// with the position of the value it concerns in the message.
pub(super) fn tell(
    file: &LitStr,
    path: &str,
    positions: &Positions,
    problem: &Problem,
) -> (Tokens, String) {
    (
        (file.span(), file.span()),
        positions.describe(path, problem),
    )
}

/// The text of the file `file` names (found by `locate`), with its path as written; `tracked`
/// is set to its absolute path, for rebuilds.
pub(super) fn read_relative(
    file: &LitStr,
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<(String, String)> {
    let relative = file.value();
    let (path, looked) = locate(file);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            errors.push(
                file.span(),
                format!("cannot read `{relative}` (relative to {looked}): {e}"),
            );
            return None;
        }
    };
    // `include_bytes!` reads a relative path from the source file's directory, not from here.
    let path = std::path::absolute(&path).unwrap_or(path);
    *tracked = Some(path.display().to_string());
    Some((relative, text))
}

/// Where the path `file` names is, and where a relative one was looked for (for the error).
///
/// The crate's root (its `Cargo.toml`) comes first, so that every path that found a file before
/// still finds the same one. Only when nothing is there is the path taken relative to the source
/// file that names it, as `include_str!` does: that makes a file beside its source reachable
/// wherever the crate is built from, such as the crate trybuild writes inside `target/`. The
/// source file is known only inside a real macro expansion on Rust 1.88 or later
/// (`Span::local_file`); the CLI and the unit tests have the crate's root alone.
fn locate(file: &LitStr) -> (PathBuf, &'static str) {
    let relative = file.value();
    let root = std::env::var_os("CARGO_MANIFEST_DIR").map_or_else(|| ".".into(), PathBuf::from);
    let from_root = root.join(&relative);
    if from_root.exists() {
        return (from_root, "the crate's Cargo.toml");
    }
    let source = file.span().local_file();
    let Some(dir) = source.as_deref().and_then(Path::parent) else {
        return (from_root, "the crate's Cargo.toml");
    };
    let beside = dir.join(&relative);
    if beside.exists() {
        (beside, "this source file")
    } else {
        (from_root, "the crate's Cargo.toml or to this source file")
    }
}

/// The problems of the loaded file `relative`'s values that the derive alone sees, as messages
/// that point into it: the fields they name that the struct lacks, divisions by zero.
fn value_problems(loaded: &Loaded, relative: &str, fields: &[Field]) -> Vec<String> {
    let robot = &loaded.robot;
    let mut messages = Vec::new();
    for name in robot.fields() {
        if let Some(message) = field_error(&name, fields) {
            let at = match field_location(robot, &name) {
                (Some(joint), key) => loaded.sources.at(relative, joint, key),
                (None, _) => super::sources::prefix(relative, loaded.sources.gravity.as_ref()),
            };
            messages.push(format!("{at}{message}"));
        }
    }
    for v in robot.values().filter(|v| v.divides_by_zero()) {
        messages.push(format!("{relative}: division by zero in `{v}`"));
    }
    messages
}

/// The first joint (`None` for gravity) and file key whose value names field `name`.
fn field_location(robot: &Robot, name: &str) -> (Option<usize>, &'static str) {
    let names = |v: &Value| {
        let mut set = std::collections::BTreeSet::new();
        v.collect_fields(&mut set);
        set.contains(name)
    };
    for (i, j) in robot.joints.iter().enumerate() {
        let spring = j.link.spring.as_ref();
        let friction = j.link.friction.as_ref();
        let origin = j.frame.iter().flat_map(|f| &f.origin.xyz).collect();
        let keys: [(&'static str, Vec<&Value>); 15] = [
            ("origin", origin),
            ("theta", vec![&j.theta]),
            ("d", vec![&j.d]),
            ("a", vec![&j.a]),
            ("alpha", vec![&j.alpha]),
            ("mass", vec![&j.link.mass]),
            ("com", j.link.com.iter().collect()),
            ("inertia", j.link.inertia.iter().collect()),
            ("actuator_inertia", vec![&j.link.actuator_inertia]),
            (
                "spring_stiffness",
                spring.map(|s| &s.stiffness).into_iter().collect(),
            ),
            ("spring_rest", spring.map(|s| &s.rest).into_iter().collect()),
            (
                "friction_viscous",
                friction.map(|f| &f.viscous).into_iter().collect(),
            ),
            (
                "friction_coulomb",
                friction.map(|f| &f.coulomb).into_iter().collect(),
            ),
            (
                "friction_offset",
                friction.map(|f| &f.offset).into_iter().collect(),
            ),
            (
                "friction_smoothing",
                friction
                    .and_then(|f| f.smoothing.as_ref())
                    .into_iter()
                    .collect(),
            ),
        ];
        if let Some((key, _)) = keys.iter().find(|(_, vs)| vs.iter().any(|v| names(v))) {
            return (Some(i), key);
        }
    }
    (None, "gravity")
}
