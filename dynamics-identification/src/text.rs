//! Numbers in words, for messages and reports.

/// Four significant digits, without exponent for everyday magnitudes.
#[must_use]
pub fn number(v: f64) -> String {
    let v = if v.abs() < 1e-12 { 0.0 } else { v };
    if v != 0.0 && (v.abs() >= 1e5 || v.abs() < 1e-3) {
        format!("{v:.2e}")
    } else {
        let magnitude = if v == 0.0 {
            0
        } else {
            v.abs().log10().floor() as i32
        };
        let digits = (3 - magnitude).clamp(0, 4);
        format!("{v:.*}", digits as usize)
    }
}
