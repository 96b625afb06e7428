//! Polynomials written as a person would, for tests: the grammar of the description's values
//! ([`crate::front::parse_value`]), whose identifiers name the polynomial's symbols.

use super::{AngleSum, Poly, Sym};
use crate::front::parse_value;
use crate::model::Value;
use crate::symbolic::Number;

impl Poly {
    /// Parses a polynomial in the grammar of description values: numbers, `+ − * / ^`,
    /// parentheses, `S1`, `C1`, `S12` (= sin(θ1 + θ2), expanded), `C12`, `qd1`, `qdd1`, `q1`
    /// (prismatic), and parameter names. Juxtaposition is not multiplication: write `*`.
    /// As in descriptions, `-x^2` is `(-x)²` and exponents run from 1 to 8; π, `deg` and a
    /// joint variable without index are not polynomials.
    ///
    /// # Errors
    /// A message when the text cannot be read or is not a polynomial.
    pub fn parse(text: &str) -> Result<Poly, String> {
        poly_of(&parse_value(text)?).map_err(|e| format!("{e} in `{text}`"))
    }
}

fn poly_of(v: &Value) -> Result<Poly, String> {
    Ok(match v {
        Value::Num(n) => Poly::constant(*n),
        Value::Field(name) => named(name),
        Value::Joint(Some(i)) => {
            let joint = i.checked_sub(1).and_then(|i| u16::try_from(i).ok());
            Poly::sym(Sym::Q(joint.ok_or("joints are numbered from 1")?))
        }
        Value::Joint(None) => return Err("write the joint variable with its index, `q1`".into()),
        Value::Pi => return Err("π is not a polynomial".into()),
        Value::Neg(a) => poly_of(a)?.scale(Number::MINUS_ONE),
        Value::Add(a, b) => poly_of(a)?.add(&poly_of(b)?),
        Value::Sub(a, b) => poly_of(a)?.sub(&poly_of(b)?),
        Value::Mul(a, b) => poly_of(a)?.mul(&poly_of(b)?),
        Value::Div(a, b) => {
            let divisor = poly_of(b)?
                .as_constant()
                .ok_or("division by a non-number")?;
            poly_of(a)?.scale(divisor.recip().ok_or("division by zero")?)
        }
    })
}

/// The polynomial an identifier names: a velocity `qd1`, an acceleration `qdd1`, the sine or
/// cosine of a joint angle or of a sum of them (`S1`, `C12`), else a parameter.
fn named(name: &str) -> Poly {
    let index = |prefix: &str| {
        name.strip_prefix(prefix)
            .and_then(|d| d.parse::<u16>().ok())
            .and_then(|i| i.checked_sub(1))
    };
    if let Some(i) = index("qdd") {
        return Poly::sym(Sym::Qdd(i));
    }
    if let Some(i) = index("qd") {
        return Poly::sym(Sym::Qd(i));
    }
    for (prefix, cos) in [("S", false), ("C", true)] {
        if let Some(joints) = name
            .strip_prefix(prefix)
            .filter(|d| !d.is_empty())
            .and_then(joint_digits)
        {
            return trig_of_sum(cos, &joints);
        }
    }
    Poly::sym(Sym::Param(name.to_string()))
}

/// `12` → joints 0 and 1 (one digit per joint, from 1).
fn joint_digits(digits: &str) -> Option<Vec<AngleSum>> {
    digits
        .chars()
        .map(|d| {
            let i = u16::try_from(d.to_digit(10)?).ok()?.checked_sub(1)?;
            AngleSum::joint(i)
        })
        .collect()
}

/// `sin` (`cos` when `cos`) of the sum of `joints`, expanded by the addition formulas so that
/// it is in canonical form.
fn trig_of_sum(cos: bool, joints: &[AngleSum]) -> Poly {
    let (mut s, mut c) = (Poly::constant(Number::ZERO), Poly::constant(Number::ONE));
    for &j in joints {
        let (sj, cj) = (Poly::sym(Sym::Sin(j)), Poly::sym(Sym::Cos(j)));
        let next_sin = s.mul(&cj).add(&c.mul(&sj));
        let next_cos = c.mul(&cj).sub(&s.mul(&sj));
        s = next_sin;
        c = next_cos;
    }
    if cos {
        c
    } else {
        s
    }
}
