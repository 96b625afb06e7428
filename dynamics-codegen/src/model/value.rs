//! Values of a robot description: exact literals and expressions over struct fields, as the
//! syntax tree the front end parses (`front::value` gives the grammar). `90 deg` is stored as
//! `90 · π/180`, so [`Value::pi_multiple`] recovers exactly π/2 and its sine and cosine stay exact.

use crate::symbolic::Number;
use std::collections::BTreeSet;
use std::ops::{Add, Mul, Neg, Sub};

/// A value: a literal or an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// An exact number.
    Num(Number),
    /// π.
    Pi,
    /// A struct field.
    Field(String),
    /// The joint variable, with the index written after `q` (1-based), if any.
    Joint(Option<usize>),
    /// `−a`.
    Neg(Box<Value>),
    /// `a + b`.
    Add(Box<Value>, Box<Value>),
    /// `a − b`.
    Sub(Box<Value>, Box<Value>),
    /// `a · b`.
    Mul(Box<Value>, Box<Value>),
    /// `a / b`.
    Div(Box<Value>, Box<Value>),
}

impl Value {
    /// Zero.
    #[must_use]
    pub fn zero() -> Value {
        Value::Num(Number::ZERO)
    }

    /// A number, made exact where it is a short decimal.
    #[must_use]
    pub fn from_f64(x: f64) -> Value {
        Value::Num(Number::from_f64(x))
    }

    /// Whether the value is the literal zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        matches!(self, Value::Num(n) if n.is_zero())
    }

    pub(crate) fn collect_fields(&self, out: &mut BTreeSet<String>) {
        match self {
            Value::Field(f) => {
                out.insert(f.clone());
            }
            Value::Neg(a) => a.collect_fields(out),
            Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
                a.collect_fields(out);
                b.collect_fields(out);
            }
            Value::Num(_) | Value::Pi | Value::Joint(_) => {}
        }
    }

    /// The number of nodes of the expression tree.
    pub(crate) fn size(&self) -> usize {
        match self {
            Value::Neg(a) => 1 + a.size(),
            Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
                1 + a.size() + b.size()
            }
            Value::Num(_) | Value::Pi | Value::Field(_) | Value::Joint(_) => 1,
        }
    }

    /// How often the joint variable occurs.
    #[must_use]
    pub fn joint_occurrences(&self) -> usize {
        match self {
            Value::Joint(_) => 1,
            Value::Neg(a) => a.joint_occurrences(),
            Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
                a.joint_occurrences() + b.joint_occurrences()
            }
            Value::Num(_) | Value::Pi | Value::Field(_) => 0,
        }
    }

    /// Splits `q`, `q + o`, `o + q`, `q − o` into the offset `o`; `None` if the joint variable
    /// appears in another way.
    #[must_use]
    pub fn joint_offset(&self) -> Option<Value> {
        match self {
            Value::Joint(_) => Some(Value::zero()),
            Value::Add(a, b) if matches!(**a, Value::Joint(_)) && b.joint_occurrences() == 0 => {
                Some((**b).clone())
            }
            Value::Add(a, b) if matches!(**b, Value::Joint(_)) && a.joint_occurrences() == 0 => {
                Some((**a).clone())
            }
            Value::Sub(a, b) if matches!(**a, Value::Joint(_)) && b.joint_occurrences() == 0 => {
                Some(Value::Neg(b.clone()))
            }
            _ => None,
        }
    }

    /// The value as an exact multiple of π, if it is one: `90 deg` and `pi / 2` give `1/2`, and
    /// so does the float nearest to π/2 (as description files store it).
    #[must_use]
    pub fn pi_multiple(&self) -> Option<Number> {
        match self {
            Value::Num(n) if n.is_zero() => Some(Number::ZERO),
            Value::Num(n) => {
                let x = n.to_f64();
                (-16i64..=16)
                    .filter(|k| *k != 0)
                    .find(|k| {
                        #[allow(clippy::cast_precision_loss)]
                        let kf = *k as f64;
                        (kf * std::f64::consts::FRAC_PI_2 - x).abs() <= 2.0 * f64::EPSILON * x.abs()
                    })
                    .and_then(|k| Number::ratio(i128::from(k), 2))
            }
            Value::Pi => Some(Number::ONE),
            Value::Neg(a) => a.pi_multiple().map(Number::neg),
            Value::Add(a, b) => Some(a.pi_multiple()?.add(b.pi_multiple()?)),
            Value::Sub(a, b) => Some(a.pi_multiple()?.sub(b.pi_multiple()?)),
            Value::Mul(a, b) => match (a.exact(), b.exact()) {
                (Some(k), _) => Some(k.mul(b.pi_multiple()?)),
                (_, Some(k)) => Some(k.mul(a.pi_multiple()?)),
                _ => None,
            },
            Value::Div(a, b) => Some(a.pi_multiple()?.mul(b.exact()?.recip()?)),
            Value::Field(_) | Value::Joint(_) => None,
        }
    }

    /// Whether the value divides by a literal zero somewhere (`1 / 0`, `m / (2 - 2)`).
    #[must_use]
    pub fn divides_by_zero(&self) -> bool {
        match self {
            Value::Div(a, b) => a.divides_by_zero() || b.exact().is_some_and(|x| x.is_zero()),
            Value::Neg(a) => a.divides_by_zero(),
            Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) => {
                a.divides_by_zero() || b.divides_by_zero()
            }
            Value::Num(_) | Value::Pi | Value::Field(_) | Value::Joint(_) => false,
        }
    }

    /// The value as an exact number, if it is one (π is not).
    #[must_use]
    pub fn exact(&self) -> Option<Number> {
        match self {
            Value::Num(n) => Some(*n),
            Value::Neg(a) => Some(a.exact()?.neg()),
            Value::Add(a, b) => Some(a.exact()?.add(b.exact()?)),
            Value::Sub(a, b) => Some(a.exact()?.sub(b.exact()?)),
            Value::Mul(a, b) => Some(a.exact()?.mul(b.exact()?)),
            Value::Div(a, b) => a.exact()?.mul(b.exact()?.recip()?).into(),
            Value::Pi | Value::Field(_) | Value::Joint(_) => None,
        }
    }

    /// The value with fields read from `field` (π as `f64`); `None` if it names the joint
    /// variable.
    pub fn eval(&self, field: &dyn Fn(&str) -> Option<f64>) -> Option<f64> {
        Some(match self {
            Value::Num(n) => n.to_f64(),
            Value::Pi => std::f64::consts::PI,
            Value::Field(f) => field(f)?,
            Value::Joint(_) => return None,
            Value::Neg(a) => -a.eval(field)?,
            Value::Add(a, b) => a.eval(field)? + b.eval(field)?,
            Value::Sub(a, b) => a.eval(field)? - b.eval(field)?,
            Value::Mul(a, b) => a.eval(field)? * b.eval(field)?,
            Value::Div(a, b) => a.eval(field)? / b.eval(field)?,
        })
    }
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Num(n) => write!(f, "{n}"),
            Value::Pi => write!(f, "pi"),
            Value::Field(x) => write!(f, "{x}"),
            Value::Joint(None) => write!(f, "q"),
            Value::Joint(Some(i)) => write!(f, "q{i}"),
            Value::Neg(a) => write!(f, "-({a})"),
            Value::Add(a, b) => write!(f, "({a} + {b})"),
            Value::Sub(a, b) => write!(f, "({a} - {b})"),
            Value::Mul(a, b) => write!(f, "{a} * {b}"),
            Value::Div(a, b) => write!(f, "{a} / ({b})"),
        }
    }
}

impl Default for Value {
    fn default() -> Value {
        Value::zero()
    }
}
