//! The values of a robot's options on the command line, checked against the robot: one per
//! joint (`--q`, `--tau`), and its parameters (`--set NAME=VALUE`).

use super::{usage, Failure};
use crate::args::{Numbers, Setting};
use dynamics_codegen::model::{Robot, Value};
use dynamics_codegen::Numeric;

/// One value per joint, zeros when the option is not given.
pub(super) fn joints(
    command: &str,
    option: &str,
    given: Option<&Numbers>,
    n: usize,
) -> Result<Vec<f64>, Failure> {
    per(command, option, given, n, &format!("{n} joints"))
}

/// One value per coordinate of `robot` (per joint where no joint follows another), zeros when
/// the option is not given.
pub(super) fn coordinates(
    command: &str,
    option: &str,
    given: Option<&Numbers>,
    robot: &Robot,
) -> Result<Vec<f64>, Failure> {
    let n = robot.coordinates().len();
    per(command, option, given, n, &joint_count(robot))
}

/// `n` values, zeros when the option is not given; `has` says how many the robot has.
fn per(
    command: &str,
    option: &str,
    given: Option<&Numbers>,
    n: usize,
    has: &str,
) -> Result<Vec<f64>, Failure> {
    match given {
        None => Ok(vec![0.0; n]),
        Some(Numbers(v)) if v.len() == n => Ok(v.clone()),
        Some(Numbers(v)) => Err(usage(
            command,
            &format!("{option}: {} values given, the robot has {has}", v.len()),
        )),
    }
}

/// "6 joints", or "3 coordinates (4 joints, 1 of them mimic)" for a robot with mimic joints,
/// which follow others and are not coordinates.
pub(super) fn joint_count(robot: &Robot) -> String {
    let (joints, coordinates) = (robot.dof(), robot.coordinates().len());
    if joints == coordinates {
        return format!("{joints} joints");
    }
    let mimic = joints - coordinates;
    format!("{coordinates} coordinates ({joints} joints, {mimic} of them mimic)")
}

/// The value of each of `robot`'s parameters, in the order of its fields, as [`parameters`]
/// gives them, checked as a description's numbers are: the masses, actuator inertias, springs
/// and friction coefficients they give (`--set m1=-1`: a negative mass) refused where a file's
/// would be. (Not the inertia tensors, which a description may exempt from its checks.)
pub(super) fn settings(
    command: &str,
    robot: &Robot,
    sets: &[Setting],
) -> Result<Vec<f64>, Failure> {
    let fields = robot.fields();
    let values = parameters(command, &fields, sets)?;
    let lookup = |name: &str| fields.iter().position(|f| f == name).map(|k| values[k]);
    let mut numbers = robot.clone();
    for joint in &mut numbers.joints {
        let link = &mut joint.link;
        let spring = link
            .spring
            .iter_mut()
            .flat_map(|s| [&mut s.stiffness, &mut s.rest]);
        let friction = link.friction.iter_mut().flat_map(|f| {
            [&mut f.viscous, &mut f.coulomb, &mut f.offset]
                .into_iter()
                .chain(f.smoothing.as_mut())
        });
        for value in [&mut link.mass, &mut link.actuator_inertia]
            .into_iter()
            .chain(spring)
            .chain(friction)
        {
            if let Some(x) = value.eval(&lookup) {
                *value = Value::from_f64(x);
            }
        }
    }
    let problems = dynamics_codegen::problems(&numbers, false);
    if problems.is_empty() {
        Ok(values)
    } else {
        let message = format!("--set: with these values, {}", problems.join("; "));
        Err(usage(command, &message))
    }
}

/// The value of each of the robot's parameters, in the order of its fields: each set exactly
/// once, none unknown.
pub(super) fn parameters(
    command: &str,
    fields: &[String],
    sets: &[Setting],
) -> Result<Vec<f64>, Failure> {
    if let Some(s) = sets.iter().find(|s| !fields.contains(&s.name)) {
        let known = if fields.is_empty() {
            "it has none".to_string()
        } else {
            format!("expected one of {}", fields.join(", "))
        };
        return Err(usage(
            command,
            &format!("--set: the robot has no parameter `{}`; {known}", s.name),
        ));
    }
    fields
        .iter()
        .map(
            |f| match sets.iter().filter(|s| &s.name == f).collect::<Vec<_>>()[..] {
                [s] => Ok(s.value),
                [] => Err(usage(
                    command,
                    &format!("the robot has a parameter `{f}`: give --set {f}=VALUE"),
                )),
                _ => Err(usage(
                    command,
                    &format!("--set: `{f}` given more than once"),
                )),
            },
        )
        .collect()
}

/// The robot evaluated numerically, its parameters set by `--set`.
pub(super) fn numeric(robot: &Robot, command: &str, sets: &[Setting]) -> Result<Numeric, Failure> {
    let fields = robot.fields();
    let values = settings(command, robot, sets)?;
    let named: Vec<(&str, f64)> = fields.iter().map(String::as_str).zip(values).collect();
    // Every field has a value: `parameters` checked.
    Numeric::new(robot, &named).map_err(|e| Failure::File(format!("no value for `{}`", e.0)))
}
