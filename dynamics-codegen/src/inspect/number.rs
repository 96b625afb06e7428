//! Numbers as the book prints them: integers, small fractions (`1/2`, `4/3`) and short
//! decimals.

use crate::symbolic::Number;

/// Denominators the book writes as fractions: 2, 3, 4, 6, 12, … (only factors 2 and 3).
pub(super) fn is_small_fraction(mut d: i128) -> bool {
    if d > 48 {
        return false;
    }
    for p in [2, 3] {
        while d % p == 0 {
            d /= p;
        }
    }
    d == 1
}

/// A number as a short decimal: exact where it has at most 8 decimals, else 6 significant
/// digits.
pub(super) fn decimal(x: Number) -> String {
    if let Number::Rational(_, mut d) = x {
        let (mut twos, mut fives) = (0, 0);
        while d % 2 == 0 {
            d /= 2;
            twos += 1;
        }
        while d % 5 == 0 {
            d /= 5;
            fives += 1;
        }
        let places = twos.max(fives);
        if d == 1 && places <= 8 {
            return trim(format!("{:.*}", places, x.to_f64()));
        }
    }
    let v = x.to_f64();
    if v == 0.0 {
        return "0".into();
    }
    let exponent = v.abs().log10().floor();
    if (-4.0..6.0).contains(&exponent) {
        // 6 significant digits
        let places = (5.0 - exponent).max(0.0) as usize;
        trim(format!("{v:.places$}"))
    } else {
        let s = format!("{v:.5e}");
        match s.split_once('e') {
            Some((mantissa, exp)) => format!("{}e{exp}", trim(mantissa.to_string())),
            None => s,
        }
    }
}

/// Drops the trailing zeros of a decimal fraction, and its point if nothing is left after it.
fn trim(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}
