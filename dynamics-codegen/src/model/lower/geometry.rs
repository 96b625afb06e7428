//! Vectors of [`Value`]s for the lowering: dot and cross products, unit vectors and angles that
//! stay exact where the inputs are (axis-aligned directions, quarter turns) and fall back to
//! floats (`Number::Float`) where only a float will do.

use crate::model::Value;
use crate::symbolic::Number;

/// A vector of values.
pub(super) type Vec3 = [Value; 3];

/// A float residue below this is rounding noise of products of floats (sines and cosines of
/// generic angles), taken as exactly 0 (or ±1 for a direction's component), so that a zero
/// term does not survive as `1e-17`. It is far below any length or inertia a robot has.
pub const NOISE_TOLERANCE: f64 = 1e-12;

/// A float.
pub(super) fn float(x: f64) -> Value {
    Value::num(Number::from_float(x))
}

/// `v` as a number, if it is one.
pub(super) fn number(v: &Value) -> Option<f64> {
    v.exact().map(Number::to_f64)
}

/// `v` with a float residue within [`NOISE_TOLERANCE`] of 0 or ±1 made exact; other values
/// (exact numbers, expressions over fields) unchanged.
pub(super) fn clean(v: Value) -> Value {
    match v.exact() {
        Some(Number::Float(x)) => {
            for exact in [0.0, 1.0, -1.0] {
                if (x - exact).abs() <= NOISE_TOLERANCE {
                    return Value::from_f64(exact);
                }
            }
            Value::num(Number::Float(x))
        }
        Some(n) => Value::num(n),
        None => v,
    }
}

/// Every component cleaned with [`clean`].
pub(super) fn clean3(v: Vec3) -> Vec3 {
    v.map(clean)
}

/// `a · b`.
pub(super) fn dot(a: &Vec3, b: &Vec3) -> Value {
    clean((0..3).fold(Value::zero(), |acc, k| acc + a[k].clone() * b[k].clone()))
}

/// `a × b`.
pub(super) fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    clean3(std::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone()
    }))
}

/// `a + b`.
pub(super) fn add(a: &Vec3, b: &Vec3) -> Vec3 {
    clean3(std::array::from_fn(|k| a[k].clone() + b[k].clone()))
}

/// `a − b`.
pub(super) fn sub(a: &Vec3, b: &Vec3) -> Vec3 {
    clean3(std::array::from_fn(|k| a[k].clone() - b[k].clone()))
}

/// `s · v`.
pub(super) fn scale(s: &Value, v: &Vec3) -> Vec3 {
    clean3(v.clone().map(|x| s.clone() * x))
}

/// `−v`.
pub(super) fn negate(v: &Vec3) -> Vec3 {
    v.clone().map(|x| -x)
}

/// Whether every component is exactly zero.
pub(super) fn is_zero(v: &Vec3) -> bool {
    v.iter().all(Value::is_zero)
}

/// Unit vector `k` (0 x, 1 y, 2 z).
pub(super) fn unit(k: usize) -> Vec3 {
    std::array::from_fn(|i| if i == k { Value::one() } else { Value::zero() })
}

/// `v / |v|` for a vector of numbers, not zero: exact where `v` lies along a coordinate axis or
/// its squared length is exactly 1, floats otherwise; `None` if a component names a field.
pub(super) fn normalize(v: &Vec3) -> Option<Vec3> {
    let nonzero: Vec<usize> = (0..3).filter(|&k| !v[k].is_zero()).collect();
    if let [k] = nonzero[..] {
        let sign = number(&v[k])?.signum();
        return Some(scale(&Value::from_f64(sign), &unit(k)));
    }
    let squared = dot(v, v).exact()?;
    if squared.is_one() {
        return Some(v.clone());
    }
    let length = squared.to_f64().sqrt();
    Some(clean3(std::array::from_fn(|k| {
        v[k].clone() * float(1.0 / length)
    })))
}

/// The angle that turns `from` into `to` about `about` (unit vectors, `from` and `to`
/// perpendicular to `about`): an exact multiple of π/2 where its sine and cosine are exactly
/// 0 and ±1, the float `atan2(sin, cos)` otherwise.
pub(super) fn angle(from: &Vec3, to: &Vec3, about: &Vec3) -> Value {
    let cos = dot(from, to);
    let sin = dot(&cross(from, to), about);
    let exact = |v: &Value| {
        v.exact()
            .filter(|n| n.is_exact())
            .and_then(Number::as_integer)
    };
    if let (Some(s), Some(c)) = (exact(&sin), exact(&cos)) {
        let quarters = match (s, c) {
            (0, 1) => Some(0),
            (1, 0) => Some(1),
            (0, -1) => Some(2),
            (-1, 0) => Some(-1),
            _ => None,
        };
        if let Some(k) = quarters {
            let half_turns = Number::ratio(k, 2).expect("a small ratio");
            return Value::num(half_turns) * Value::Pi;
        }
    }
    let (s, c) = (
        number(&sin).expect("directions are numbers"),
        number(&cos).expect("directions are numbers"),
    );
    float(s.atan2(c))
}
