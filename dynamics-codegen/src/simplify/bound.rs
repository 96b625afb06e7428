//! Bounds of each symbol's absolute value over an [`Envelope`], by interval arithmetic, and of
//! a monomial's as the product of its factors' bounds.

use crate::model::Envelope;
use crate::poly::{AngleSum, Monomial, Sym};
use crate::symbolic::Number;
use std::f64::consts::{FRAC_PI_2, PI};

/// The largest `|sin x|` for `x` in `[lo, hi]`: 1 where the interval holds a peak
/// `π/2 + kπ` (or is at least π wide), else the larger end. Rounding is taken outward: a peak
/// within 1e-12 of an end counts as inside, and an end's value is raised by 1e-12.
#[must_use]
pub fn max_abs_sin(lo: f64, hi: f64) -> f64 {
    if hi - lo >= PI {
        return 1.0;
    }
    let k = ((lo - FRAC_PI_2) / PI).ceil();
    let peak = FRAC_PI_2 + k * PI;
    if peak <= hi + 1e-12 || peak - PI >= lo - 1e-12 {
        return 1.0;
    }
    (lo.sin().abs().max(hi.sin().abs()) + 1e-12).min(1.0)
}

/// The largest `|cos x|` for `x` in `[lo, hi]`, as [`max_abs_sin`] of the shifted interval.
#[must_use]
pub fn max_abs_cos(lo: f64, hi: f64) -> f64 {
    max_abs_sin(lo + FRAC_PI_2, hi + FRAC_PI_2)
}

/// The interval of the angle sum `a` (each joint's range plus its constant offset).
fn angle_range(a: AngleSum, envelope: &Envelope, offsets: &[f64]) -> Option<(f64, f64)> {
    let mut range = (0.0, 0.0);
    for j in a.joints().map(usize::from) {
        let joint = envelope.joints.get(j)?;
        let offset = offsets.get(j).copied().unwrap_or(0.0);
        range.0 += joint.lower + offset;
        range.1 += joint.upper + offset;
    }
    Some(range)
}

/// The largest `|s|` over the envelope; `Err` for a parameter, which no envelope bounds.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn symbol_bound(s: &Sym, envelope: &Envelope, offsets: &[f64]) -> Result<f64, String> {
    let joint = |i: &u16| {
        envelope
            .joints
            .get(usize::from(*i))
            .ok_or_else(|| format!("joint {} is outside the envelope", i + 1))
    };
    Ok(match s {
        Sym::Param(p) => {
            return Err(format!(
                "the parameter `{p}` has no bound over the envelope: give it a value in the description"
            ))
        }
        Sym::Q(i) => {
            let j = joint(i)?;
            j.lower.abs().max(j.upper.abs())
        }
        Sym::Sin(a) | Sym::Cos(a) => {
            let (lo, hi) = angle_range(*a, envelope, offsets)
                .ok_or_else(|| format!("an angle of {s} is outside the envelope"))?;
            if matches!(s, Sym::Sin(_)) {
                max_abs_sin(lo, hi)
            } else {
                max_abs_cos(lo, hi)
            }
        }
        Sym::MimicSin(a) | Sym::MimicCos(a) => {
            let j = joint(&a.joint)?;
            let (lo, hi) = a.range(j.lower, j.upper);
            if matches!(s, Sym::MimicSin(_)) {
                max_abs_sin(lo, hi)
            } else {
                max_abs_cos(lo, hi)
            }
        }
        Sym::Qd(i) => joint(i)?.speed,
        Sym::Qdd(i) => joint(i)?.acceleration,
        Sym::Sign(_) | Sym::Tanh(_) => 1.0,
    })
}

/// The largest `|c m|` over the envelope: `|c|` times each factor's bound to its power, raised
/// by a relative 1e-12 for the rounding of the products.
pub(super) fn term_bound(
    m: &Monomial,
    c: Number,
    envelope: &Envelope,
    offsets: &[f64],
) -> Result<f64, String> {
    let mut bound = c.to_f64().abs();
    for (s, e) in m.factors() {
        let b = symbol_bound(s, envelope, offsets)?;
        bound *= b.powi(i32::try_from(*e).unwrap_or(i32::MAX));
    }
    Ok(bound * (1.0 + 1e-12))
}
