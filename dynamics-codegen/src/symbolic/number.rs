//! Exact numbers for the symbolic engine.
//!
//! Literals are kept as rationals (`0.4318` is `4318/10000`) so that terms that must cancel do
//! cancel; a result that would overflow `i128` falls back to `f64`, which is then exact to
//! rounding only.

use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Neg};

/// A rational with `i128` numerator and denominator, or an `f64` where a rational overflowed.
#[derive(Clone, Copy, Debug)]
pub enum Number {
    /// `num / den`, reduced, `den > 0`.
    Rational(i128, i128),
    /// A float (never NaN; `-0.0` is stored as `0.0`).
    Float(f64),
}

fn gcd(a: i128, b: i128) -> i128 {
    // The constants of a trace are small: in 64 bits the remainders are one instruction each,
    // where those of `i128` are library calls.
    if let (Ok(a), Ok(b)) = (
        u64::try_from(a.unsigned_abs()),
        u64::try_from(b.unsigned_abs()),
    ) {
        return i128::from(gcd_u64(a, b));
    }
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

/// `a / b` of a divisor from [`gcd`], without the library's division where it is 1.
fn divide(a: i128, b: i128) -> i128 {
    if b == 1 {
        a
    } else {
        a / b
    }
}

impl Number {
    /// Zero.
    pub const ZERO: Number = Number::Rational(0, 1);
    /// One.
    pub const ONE: Number = Number::Rational(1, 1);
    /// Minus one.
    pub const MINUS_ONE: Number = Number::Rational(-1, 1);

    /// An integer.
    #[must_use]
    pub fn int(n: i64) -> Number {
        Number::Rational(i128::from(n), 1)
    }

    /// `num / den`, reduced; `None` for a zero denominator or on overflow.
    #[must_use]
    pub fn ratio(num: i128, den: i128) -> Option<Number> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (divide(num, g), divide(den, g));
        if d < 0 {
            n = n.checked_neg()?;
            d = d.checked_neg()?;
        }
        Some(Number::Rational(n, d))
    }

    /// A float, turned into a rational where it is a short decimal (`0.4318` → 4318/10000):
    /// the shortest decimal that rounds to the float is taken as the intended value.
    #[must_use]
    pub fn from_f64(x: f64) -> Number {
        if x == 0.0 {
            return Number::ZERO;
        }
        if !x.is_finite() {
            return Number::Float(x);
        }
        Number::parse_decimal(&format!("{x}")).unwrap_or(Number::Float(x))
    }

    /// Parses a decimal literal such as `12`, `-0.4318`, `1.5e-3` exactly.
    #[must_use]
    pub fn parse_decimal(text: &str) -> Option<Number> {
        let text = text.replace('_', "");
        let (neg, body) = match text.strip_prefix('-') {
            Some(rest) => (true, rest.to_string()),
            None => (false, text.clone()),
        };
        let (mantissa, exponent) = match body.find(['e', 'E']) {
            Some(pos) => (&body[..pos], body[pos + 1..].parse::<i32>().ok()?),
            None => (&body[..], 0),
        };
        let (int_part, frac_part) = match mantissa.find('.') {
            Some(pos) => (&mantissa[..pos], &mantissa[pos + 1..]),
            None => (mantissa, ""),
        };
        if int_part.is_empty() && frac_part.is_empty() {
            return None;
        }
        if !int_part
            .chars()
            .chain(frac_part.chars())
            .all(|c| c.is_ascii_digit())
        {
            return None;
        }
        let digits = format!("{int_part}{frac_part}");
        let digits = digits.trim_start_matches('0');
        let value: i128 = if digits.is_empty() {
            0
        } else {
            digits.parse().ok()?
        };
        let scale = exponent.checked_sub(i32::try_from(frac_part.len()).ok()?)?;
        let pow = |e: u32| 10i128.checked_pow(e);
        let n = if scale >= 0 {
            Number::Rational(value.checked_mul(pow(scale.unsigned_abs())?)?, 1)
        } else {
            Number::ratio(value, pow(scale.unsigned_abs())?)?
        };
        Some(if neg { n.neg() } else { n })
    }

    /// The nearest `f64` (correctly rounded when numerator and denominator are below 2^53).
    #[must_use]
    #[allow(clippy::cast_precision_loss)]
    pub fn to_f64(self) -> f64 {
        match self {
            // The same rounding as from i128, without its slow software conversion.
            Number::Rational(n, d) => match (i64::try_from(n), i64::try_from(d)) {
                (Ok(n), Ok(d)) => n as f64 / d as f64,
                _ => n as f64 / d as f64,
            },
            Number::Float(x) => x,
        }
    }

    /// Whether the number is exactly zero.
    #[must_use]
    pub fn is_zero(self) -> bool {
        match self {
            Number::Rational(n, _) => n == 0,
            Number::Float(x) => x == 0.0,
        }
    }

    /// Whether the number is exactly one.
    #[must_use]
    pub fn is_one(self) -> bool {
        matches!(self, Number::Rational(1, 1))
    }

    /// Whether the number is exactly minus one.
    #[must_use]
    pub fn is_minus_one(self) -> bool {
        matches!(self, Number::Rational(-1, 1))
    }

    /// Whether the number is negative.
    #[must_use]
    pub fn is_negative(self) -> bool {
        match self {
            Number::Rational(n, _) => n < 0,
            Number::Float(x) => x < 0.0,
        }
    }

    /// Whether the number is an exact rational.
    #[must_use]
    pub fn is_exact(self) -> bool {
        matches!(self, Number::Rational(..))
    }

    /// The integer value, if the number is an exact integer.
    #[must_use]
    pub fn as_integer(self) -> Option<i128> {
        match self {
            Number::Rational(n, 1) => Some(n),
            _ => None,
        }
    }

    fn float(x: f64) -> Number {
        Number::Float(if x == 0.0 { 0.0 } else { x })
    }

    /// `1 / self`; `None` for zero.
    #[must_use]
    pub fn recip(self) -> Option<Number> {
        if self.is_zero() {
            return None;
        }
        Some(match self {
            Number::Rational(n, d) => {
                Number::ratio(d, n).unwrap_or_else(|| Number::float(1.0 / self.to_f64()))
            }
            Number::Float(x) => Number::float(1.0 / x),
        })
    }

    fn key(self) -> (u8, i128, i128) {
        match self {
            Number::Rational(n, d) => (0, n, d),
            Number::Float(x) => (1, i128::from(x.to_bits()), 0),
        }
    }
}

impl PartialEq for Number {
    fn eq(&self, other: &Number) -> bool {
        self.key() == other.key()
    }
}

impl Eq for Number {}

impl Hash for Number {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.key().hash(state);
    }
}

impl PartialOrd for Number {
    fn partial_cmp(&self, other: &Number) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Number {
    /// A total order for sorting (by value, exact ties by representation).
    fn cmp(&self, other: &Number) -> Ordering {
        self.to_f64()
            .total_cmp(&other.to_f64())
            .then_with(|| self.key().cmp(&other.key()))
    }
}

impl fmt::Display for Number {
    /// `3`, `-1/2`, or a float in its shortest round-trip form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Number::Rational(n, 1) => write!(f, "{n}"),
            Number::Rational(n, d) => write!(f, "{n}/{d}"),
            Number::Float(x) => write!(f, "{x:?}"),
        }
    }
}

impl std::ops::Add for Number {
    type Output = Number;
    fn add(self, other: Number) -> Number {
        // Integers, the most common case: what the general rule gives, without its gcd.
        if let (Number::Rational(a, 1), Number::Rational(c, 1)) = (self, other) {
            if let Some(sum) = a.checked_add(c) {
                return Number::Rational(sum, 1);
            }
        }
        if let (Number::Rational(a, b), Number::Rational(c, d)) = (self, other) {
            let exact = (|| {
                let num = a.checked_mul(d)?.checked_add(c.checked_mul(b)?)?;
                Number::ratio(num, b.checked_mul(d)?)
            })();
            if let Some(n) = exact {
                return n;
            }
        }
        Number::float(self.to_f64() + other.to_f64())
    }
}

#[allow(clippy::suspicious_arithmetic_impl)] // reduces by gcds before multiplying
impl std::ops::Mul for Number {
    type Output = Number;
    fn mul(self, other: Number) -> Number {
        if let (Number::Rational(a, 1), Number::Rational(c, 1)) = (self, other) {
            if let Some(product) = a.checked_mul(c) {
                return Number::Rational(product, 1);
            }
        }
        if let (Number::Rational(a, b), Number::Rational(c, d)) = (self, other) {
            let g1 = gcd(a, d).max(1);
            let g2 = gcd(c, b).max(1);
            let exact = (|| {
                let num = divide(a, g1).checked_mul(divide(c, g2))?;
                Number::ratio(num, divide(b, g2).checked_mul(divide(d, g1))?)
            })();
            if let Some(n) = exact {
                return n;
            }
        }
        Number::float(self.to_f64() * other.to_f64())
    }
}

impl std::ops::Neg for Number {
    type Output = Number;
    fn neg(self) -> Number {
        match self {
            Number::Rational(n, d) => match n.checked_neg() {
                Some(m) => Number::Rational(m, d),
                None => Number::float(-self.to_f64()),
            },
            Number::Float(x) => Number::float(-x),
        }
    }
}

impl std::ops::Sub for Number {
    type Output = Number;
    fn sub(self, other: Number) -> Number {
        self.add(other.neg())
    }
}

impl Number {
    /// A float result of a numeric function, snapped to an exact rational when it is one of
    /// 0, ±1, ±1/2 to within 4 ulp (so that `cos(π/2)` is an exact 0).
    #[must_use]
    pub fn from_float(x: f64) -> Number {
        for exact in [0.0, 1.0, -1.0, 0.5, -0.5] {
            if (x - exact).abs() <= 4.0 * f64::EPSILON {
                return Number::from_f64(exact);
            }
        }
        Number::Float(x)
    }
}
