//! The unit check of angles (θ and α of every D-H row): a term written as a plain number whose
//! magnitude exceeds 2π (`90` in `q + 90`, `-90`, `pi/2 + 90`) is almost always a forgotten
//! `deg`, so it is an error that says so; `90 rad` keeps it in radians. Terms with `pi`, a
//! unit or a field are taken as written (`pi/2 + 3`, `2 * pi`, `q + offset`).

use super::value::Unitless;
use crate::symbolic::Number;

/// The first of `unitless` (the plain-number terms of an angle) that exceeds 2π in magnitude,
/// with the message for it; `quoted` writes the suggestions as description-file strings.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn unitless_angle(unitless: &[Unitless], quoted: bool) -> Option<(&Unitless, String)> {
    let term = unitless
        .iter()
        .find(|t| t.value.to_f64().abs() > std::f64::consts::TAU)?;
    Some((term, message(term.value, quoted)))
}

/// "an angle of 90 without a unit is 90 radians (5157°): write `90 deg`, or `90 rad` if you
/// mean radians".
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn message(value: Number, quoted: bool) -> String {
    let x = value.to_f64();
    // As a decimal: `6.3`, not the exact `63/10` (which would read as 63 / (10 deg)).
    let text = match value {
        Number::Rational(n, 1) => n.to_string(),
        _ => format!("{x}"),
    };
    let q = if quoted { "\"" } else { "" };
    format!(
        "an angle of {text} without a unit is {text} radians ({:.0}°): write `{q}{text} deg{q}`, \
         or `{q}{text} rad{q}` if you mean radians",
        x.to_degrees()
    )
}
