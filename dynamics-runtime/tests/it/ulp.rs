//! Errors in ulps, and the worst error seen, for the accuracy tests of `trig.rs` and
//! `friction_functions.rs`.

use dynamics_runtime::Real;

/// Spacing of the `f64`s at the magnitude of `y`.
pub fn ulp_f64(y: f64) -> f64 {
    let exponent = ((y.abs().to_bits() >> 52) as i32).max(1) - 1075;
    2f64.powi(exponent)
}

/// Spacing of the `f32`s at the magnitude of `y`.
pub fn ulp_f32(y: f64) -> f64 {
    let exponent = y.abs().log2().floor().max(-126.0) as i32 - 23;
    2f64.powi(exponent)
}

/// Error of `got` in ulps of `want`; 0 when both are the same NaN-ness or equal.
pub fn err_f64(got: f64, want: f64) -> f64 {
    if got == want || (got.is_nan() && want.is_nan()) {
        0.0
    } else {
        (got - want).abs() / ulp_f64(want)
    }
}

pub fn err_f32(got: f32, want: f64) -> f64 {
    let got = f64::from(got);
    if got == want || (got.is_nan() && want.is_nan()) {
        0.0
    } else {
        (got - want).abs() / ulp_f32(want)
    }
}

/// The worst error seen and where.
#[derive(Default)]
pub struct Worst {
    ulp: f64,
    at: f64,
    count: usize,
}

impl Worst {
    pub fn see(&mut self, ulp: f64, at: f64) {
        self.count += 1;
        if ulp > self.ulp || ulp.is_nan() {
            self.ulp = ulp;
            self.at = at;
        }
    }

    pub fn check(&self, what: &str, max: f64) {
        println!(
            "{what}: worst {:.3} ulp at x = {:e} ({} arguments)",
            self.ulp, self.at, self.count
        );
        assert!(
            self.ulp <= max,
            "{what}: {} ulp at x = {:e} (allowed {max})",
            self.ulp,
            self.at
        );
    }
}

/// Compares `f64` sine and cosine with std at `x`.
pub fn see_f64(worst: &mut Worst, x: f64) {
    let (s, c) = Real::sin_cos(x);
    worst.see(err_f64(s, x.sin()).max(err_f64(c, x.cos())), x);
}

/// Compares `f32` sine and cosine with std's `f64` ones at `x`.
pub fn see_f32(worst: &mut Worst, x: f32) {
    let (s, c) = Real::sin_cos(x);
    let wide = f64::from(x);
    worst.see(err_f32(s, wide.sin()).max(err_f32(c, wide.cos())), wide);
}
