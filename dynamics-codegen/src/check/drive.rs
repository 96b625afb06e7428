//! Physical checks on a joint's drive values known at compile time: the actuator inertia
//! (eq. 6.39, added to `M_ii`) and the spring stiffness are finite and not negative, the
//! spring's rest position finite. No override: a negative actuator inertia has no physical
//! meaning, and a negative stiffness (an unstable spring, on purpose) can still be given as a
//! struct field, whose value is read at run time and not checked.

use super::link::{short, LinkParameter, LinkProblem};
use crate::model::{Spring, Value};

/// The problems of a joint's actuator inertia and spring. Values that name struct fields are
/// not known yet and pass.
#[must_use]
pub fn drive(actuator_inertia: &Value, spring: Option<&Spring>) -> Vec<LinkProblem> {
    let actuator = not_negative(
        actuator_inertia,
        LinkParameter::ActuatorInertia,
        "the actuator inertia",
        "it adds to M_ii, and a rotor's inertia (times the gear ratio squared) is 0 or more",
    );
    let stiffness = spring.and_then(|s| {
        not_negative(
            &s.stiffness,
            LinkParameter::SpringStiffness,
            "the spring stiffness",
            "such a spring pushes away from its rest position; a stiffness is 0 or more (give \
             it as a struct field to keep an unstable spring on purpose)",
        )
    });
    let rest = spring.and_then(|s| {
        let x = s.rest.exact()?.to_f64();
        (!x.is_finite()).then(|| LinkProblem {
            parameter: LinkParameter::SpringRest,
            message: "the spring's rest position is not a finite number".into(),
        })
    });
    actuator.into_iter().chain(stiffness).chain(rest).collect()
}

/// The problem of `value` (`what`, about `parameter`) if it is a literal that is not finite or
/// is negative; `why` says why it may not be.
fn not_negative(
    value: &Value,
    parameter: LinkParameter,
    what: &str,
    why: &str,
) -> Option<LinkProblem> {
    let n = value.exact()?;
    let x = n.to_f64();
    let message = if !x.is_finite() {
        format!("{what} is not a finite number")
    } else if n.is_negative() {
        format!("{what} is negative ({}): {why}", short(x))
    } else {
        return None;
    };
    Some(LinkProblem { parameter, message })
}
