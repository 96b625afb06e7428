//! Checks on a joint's friction `f_v q̇ + f_c sign(q̇) + f_0` (or `f_c tanh(q̇ / ε)`) and on a
//! geared drive, whose actuator inertia is `N² I_rotor`, for values known at compile time:
//!
//! * the viscous and Coulomb coefficients are finite and not negative (a negative one pushes
//!   the joint along its motion, feeding it energy), the offset finite;
//! * the smoothing velocity ε is finite and positive (`tanh(q̇ / ε)` needs it);
//! * the rotor inertia is finite and not negative; the gear ratio finite and not zero. A
//!   negative ratio is a reversed drive (the motor turns against the joint): `N²` is the same.
//!
//! Values that name struct fields are read at run time and pass.

use super::link::{short, LinkParameter, LinkProblem};
use crate::model::{Friction, Value};

/// The problems of a joint's friction.
#[must_use]
pub fn friction(f: &Friction) -> Vec<LinkProblem> {
    let loss = "friction opposes the motion: a negative coefficient would feed the joint energy";
    let viscous = sign_problem(
        &f.viscous,
        LinkParameter::FrictionViscous,
        "the viscous friction coefficient",
        loss,
        false,
    );
    let coulomb = sign_problem(
        &f.coulomb,
        LinkParameter::FrictionCoulomb,
        "the Coulomb friction coefficient",
        loss,
        false,
    );
    let offset = finite_problem(
        &f.offset,
        LinkParameter::FrictionOffset,
        "the friction offset",
    );
    let smoothing = f.smoothing.as_ref().and_then(|eps| {
        sign_problem(
            eps,
            LinkParameter::FrictionSmoothing,
            "the friction smoothing velocity",
            "the Coulomb term is f_c tanh(qd / smoothing); leave `smoothing` out for f_c sign(qd)",
            true,
        )
    });
    viscous
        .into_iter()
        .chain(coulomb)
        .chain(offset)
        .chain(smoothing)
        .collect()
}

/// The problems of a geared drive with rotor inertia `rotor` and gear ratio `ratio`.
#[must_use]
pub fn gear(rotor: &Value, ratio: &Value) -> Vec<LinkProblem> {
    let rotor = sign_problem(
        rotor,
        LinkParameter::RotorInertia,
        "the rotor inertia",
        "the actuator inertia is gear_ratio² × rotor_inertia, and an inertia is 0 or more",
        false,
    );
    let ratio = ratio.exact().and_then(|n| {
        let message = if !n.to_f64().is_finite() {
            "the gear ratio is not a finite number"
        } else if n.is_zero() {
            "the gear ratio is zero: it is motor turns per joint turn (a negative one reverses the drive)"
        } else {
            return None;
        };
        Some(LinkProblem {
            parameter: LinkParameter::GearRatio,
            message: message.into(),
        })
    });
    rotor.into_iter().chain(ratio).collect()
}

/// The actuator inertia of a geared drive, `ratio² · rotor`, exact for literals.
#[must_use]
pub fn geared_inertia(rotor: &Value, ratio: &Value) -> Value {
    let square = Value::Mul(Box::new(ratio.clone()), Box::new(ratio.clone()));
    Value::Mul(Box::new(square), Box::new(rotor.clone()))
}

/// The problem of literal `value` (`what`, about `parameter`) if it is not finite, negative,
/// or (with `positive`) zero; `why` says why it may not be.
fn sign_problem(
    value: &Value,
    parameter: LinkParameter,
    what: &str,
    why: &str,
    positive: bool,
) -> Option<LinkProblem> {
    let n = value.exact()?;
    let x = n.to_f64();
    let message = if !x.is_finite() {
        format!("{what} is not a finite number")
    } else if n.is_negative() {
        format!("{what} is negative ({}): {why}", short(x))
    } else if positive && n.is_zero() {
        format!("{what} is zero: {why}")
    } else {
        return None;
    };
    Some(LinkProblem { parameter, message })
}

fn finite_problem(value: &Value, parameter: LinkParameter, what: &str) -> Option<LinkProblem> {
    let x = value.exact()?.to_f64();
    (!x.is_finite()).then(|| LinkProblem {
        parameter,
        message: format!("{what} is not a finite number"),
    })
}
