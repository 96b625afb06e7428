//! The derive's `file = "..."`: the description file read (relative to the crate's
//! `Cargo.toml`) into a robot, with the fields its values name and the checks of
//! [`crate::check::robot`]. Every error goes on the `file = "..."` string, with the file's name,
//! line and column in the message.

use super::errors::Errors;
use super::fields::{field_error, Field};
use super::file::{self, Loaded};
use crate::check::{self, Problem};
use crate::model::{Robot, Value};
use syn::LitStr;

/// Reads the description file `file` names; `tracked` is set to its absolute path, for
/// rebuilds. `check_inertia = false` on the derive turns off the inertia checks of every joint.
pub(super) fn robot_from_file(
    file: &LitStr,
    check_inertia: bool,
    fields: &[Field],
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<Robot> {
    let (relative, text) = read_relative(file, errors, tracked)?;
    let loaded = match file::load(&relative, &text) {
        Ok(loaded) => loaded,
        Err(e) => {
            let sep = if e.line.is_some() { "" } else { " " };
            errors.push(file.span(), format!("{relative}:{sep}{e}"));
            return None;
        }
    };
    for message in problems(&loaded, &relative, check_inertia, fields) {
        errors.push(file.span(), message);
    }
    Some(loaded.robot)
}

/// The text of the file `file` names (relative to the crate's `Cargo.toml`), with its path
/// as written; `tracked` is set to its absolute path, for rebuilds.
pub(super) fn read_relative(
    file: &LitStr,
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<(String, String)> {
    let relative = file.value();
    let base = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".to_string());
    let path = std::path::Path::new(&base).join(&relative);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            errors.push(
                file.span(),
                format!("cannot read `{relative}` (relative to the crate's Cargo.toml): {e}"),
            );
            return None;
        }
    };
    *tracked = Some(path.display().to_string());
    Some((relative, text))
}

/// Every problem of the loaded file `relative`, as messages that point into it.
pub(super) fn problems(
    loaded: &Loaded,
    relative: &str,
    check_inertia: bool,
    fields: &[Field],
) -> Vec<String> {
    let robot = &loaded.robot;
    let mut messages = Vec::new();
    for name in robot.fields() {
        if let Some(message) = field_error(&name, fields) {
            let at = match field_location(robot, &name) {
                (Some(joint), key) => loaded.at(relative, joint, key),
                (None, _) => loaded.gravity.map_or_else(
                    || format!("{relative}: "),
                    |(line, column)| format!("{relative}:{line}:{column}: "),
                ),
            };
            messages.push(format!("{at}{message}"));
        }
    }
    let flags: Vec<bool> = loaded
        .check_inertia
        .iter()
        .map(|checked| *checked && check_inertia)
        .collect();
    // The joint count is reported before the values' own errors, the links' problems after.
    let (count, links): (Vec<Problem>, Vec<Problem>) = check::robot(robot, &flags)
        .into_iter()
        .partition(|p| matches!(p, Problem::TooManyJoints { .. }));
    messages.extend(count.iter().map(|p| loaded.describe(relative, p)));
    for v in robot.values().filter(|v| v.divides_by_zero()) {
        messages.push(format!("{relative}: division by zero in `{v}`"));
    }
    messages.extend(links.iter().map(|p| loaded.describe(relative, p)));
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
