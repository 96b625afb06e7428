//! Relative error measures for comparing a computed vector with an expected one.

/// `max|got − want| / scale` over matching entries; infinite if a value of `got` is not
/// finite (`f64::max` would silently drop a NaN).
///
/// # Panics
/// If the lengths differ.
#[must_use]
pub fn error_over(got: &[f64], want: &[f64], scale: f64) -> f64 {
    assert_eq!(got.len(), want.len(), "length mismatch");
    got.iter()
        .zip(want)
        .map(|(a, b)| {
            if a.is_finite() {
                (a - b).abs() / scale
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max)
}

/// [`error_over`] with `scale = max|want|` (1 where `want` is all zeros): relative to the
/// expected vector's size however small it is, stricter than the reference data's
/// `max(1, max|want|)`.
#[must_use]
pub fn relative_error(got: &[f64], want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    error_over(got, want, if scale > 0.0 { scale } else { 1.0 })
}

#[cfg(test)]
mod tests {
    use super::{error_over, relative_error};

    #[test]
    fn measures() {
        assert_eq!(relative_error(&[1.0, 2.5], &[1.0, 2.0]), 0.25);
        assert_eq!(relative_error(&[0.5], &[0.0]), 0.5);
        assert_eq!(error_over(&[f64::NAN], &[1.0], 1.0), f64::INFINITY);
    }
}
