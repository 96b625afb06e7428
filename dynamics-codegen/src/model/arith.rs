//! Arithmetic on [`Value`]s that folds what is known: numbers combine exactly (rationals, or
//! floats where a rational overflows), and `0 + x`, `1 · x`, `0 · x`, `−(−x)` simplify, so that
//! the values the front end derives (rotated inertias, frame offsets) stay as short as the ones
//! a person would write.

use super::Value;
use crate::symbolic::Number;
use std::ops::{Add, Mul, Neg, Sub};

impl Value {
    /// A number.
    #[must_use]
    pub fn num(n: Number) -> Value {
        Value::Num(n)
    }

    /// One.
    #[must_use]
    pub fn one() -> Value {
        Value::Num(Number::ONE)
    }

    fn is_one(&self) -> bool {
        self.exact().is_some_and(Number::is_one)
    }
}

impl Add for Value {
    type Output = Value;

    fn add(self, b: Value) -> Value {
        match (self.exact(), b.exact()) {
            (Some(x), Some(y)) => Value::Num(x + y),
            (Some(x), _) if x.is_zero() => b,
            (_, Some(y)) if y.is_zero() => self,
            (_, Some(y)) if y.is_negative() => Value::Sub(Box::new(self), Box::new(Value::Num(-y))),
            _ => Value::Add(Box::new(self), Box::new(b)),
        }
    }
}

impl Sub for Value {
    type Output = Value;

    fn sub(self, b: Value) -> Value {
        match (self.exact(), b.exact()) {
            (Some(x), Some(y)) => Value::Num(x - y),
            (Some(x), _) if x.is_zero() => -b,
            (_, Some(y)) if y.is_zero() => self,
            _ => Value::Sub(Box::new(self), Box::new(b)),
        }
    }
}

impl Mul for Value {
    type Output = Value;

    fn mul(self, b: Value) -> Value {
        match (self.exact(), b.exact()) {
            (Some(x), Some(y)) => Value::Num(x * y),
            (Some(x), _) | (_, Some(x)) if x.is_zero() => Value::zero(),
            _ if self.is_one() => b,
            _ if b.is_one() => self,
            (Some(x), _) if x.is_minus_one() => -b,
            (_, Some(y)) if y.is_minus_one() => -self,
            _ => Value::Mul(Box::new(self), Box::new(b)),
        }
    }
}

impl Neg for Value {
    type Output = Value;

    fn neg(self) -> Value {
        match self {
            Value::Num(n) => Value::Num(-n),
            Value::Neg(a) => *a,
            other => Value::Neg(Box::new(other)),
        }
    }
}
