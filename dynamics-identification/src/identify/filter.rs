//! A zero-phase low-pass filter for measured signals: a 4th-order Butterworth low-pass run
//! forward and then backward over the whole signal (`filtfilt`).
//!
//! **Design.** The analog Butterworth low-pass of order N = 4 is the product of the sections
//! `1 / (s² + s/Q_k + 1)` (frequency in units of the cutoff) with `Q_k = 1 / (2 cos θ_k)`,
//! `θ_k = (2k − 1) π / (2N)`, k = 1, 2. Each becomes a digital biquad by the bilinear transform,
//! with the cutoff prewarped (`K = tan(π f_c / f_s)`):
//! `b = [K², 2K², K²] / a_0`, `a = [1, 2(K² − 1) / a_0, (1 − K/Q + K²) / a_0]`,
//! `a_0 = 1 + K/Q + K²`. Then `|H(e^{iω})|² = 1 / (1 + (tan(ω/2) / K)^{2N})`: flat in the pass
//! band, `1/2` (−3 dB) at the cutoff.
//!
//! **Zero phase.** Run forward and backward, a signal sees `|H|²` with no phase: no delay
//! between q and τ, −6 dB at the cutoff, an 8th-order roll-off. Both ends are padded by the odd
//! extension of the signal about its end values (ten time constants of the slowest section),
//! and each section starts in its steady state for the first padded value, as
//! `scipy.signal.filtfilt` does, so the ends keep the signal's level and slope.
//!
//! The filter runs on `x − x_0`, the deviation from the first sample: a constant signal stays
//! exactly constant (a joint at rest keeps an exactly zero q̇), and a large offset costs no
//! digits.

use std::f64::consts::PI;

/// The order of the Butterworth filter.
pub const ORDER: usize = 4;

/// A low-pass filter as cascaded biquads.
#[derive(Clone, Debug)]
pub struct LowPass {
    /// `[b0, b1, b2, a1, a2]` per section (`a0 = 1`).
    sections: Vec<[f64; 5]>,
    /// Samples of padding at each end.
    padding: usize,
}

impl LowPass {
    /// The Butterworth low-pass of order [`ORDER`] with cutoff `cutoff` (Hz) for samples taken
    /// at `rate` (Hz).
    ///
    /// # Errors
    /// A cutoff that is not between zero and the Nyquist frequency `rate / 2`.
    pub fn butterworth(cutoff: f64, rate: f64) -> Result<LowPass, String> {
        if !(cutoff > 0.0 && cutoff < rate / 2.0) {
            return Err(format!(
                "the cutoff {cutoff} Hz is not below the Nyquist frequency {} Hz of samples \
                 taken at {rate} Hz",
                rate / 2.0
            ));
        }
        let k = (PI * cutoff / rate).tan();
        let sections = (1..=ORDER / 2)
            .map(|s| {
                let theta = (2 * s - 1) as f64 * PI / (2 * ORDER) as f64;
                let q = 1.0 / (2.0 * theta.cos());
                let a0 = 1.0 + k / q + k * k;
                let b0 = k * k / a0;
                [
                    b0,
                    2.0 * b0,
                    b0,
                    2.0 * (k * k - 1.0) / a0,
                    (1.0 - k / q + k * k) / a0,
                ]
            })
            .collect();
        // The slowest section's impulse response decays as e^{−t ω_c / (2Q)}: ten of its time
        // constants (2Q / ω_c, in samples) of padding, which forget the start's guess to e^{−10}.
        let q_max = 1.0 / (2.0 * ((2 * (ORDER / 2) - 1) as f64 * PI / (2 * ORDER) as f64).cos());
        let padding = (10.0 * 2.0 * q_max * rate / (2.0 * PI * cutoff)).ceil() as usize;
        Ok(LowPass { sections, padding })
    }

    /// Filters `x` in place, forward and backward.
    pub fn filtfilt(&self, x: &mut [f64]) {
        let n = x.len();
        if n < 2 {
            return;
        }
        let x0 = x[0];
        let pad = self.padding.min(n - 1);
        let (first, last) = (0.0, x[n - 1] - x0);
        let mut ext: Vec<f64> = Vec::with_capacity(n + 2 * pad);
        ext.extend((1..=pad).rev().map(|k| 2.0 * first - (x[k] - x0)));
        ext.extend(x.iter().map(|v| v - x0));
        ext.extend((1..=pad).map(|k| 2.0 * last - (x[n - 1 - k] - x0)));
        self.run(&mut ext);
        ext.reverse();
        self.run(&mut ext);
        ext.reverse();
        for (v, y) in x.iter_mut().zip(&ext[pad..]) {
            *v = y + x0;
        }
    }

    /// One pass of the cascade (transposed direct form II), each section starting in its steady
    /// state for the first value.
    fn run(&self, x: &mut [f64]) {
        let Some(&u) = x.first() else {
            return;
        };
        for &[b0, b1, b2, a1, a2] in &self.sections {
            // A section's DC gain is 1, so its steady state for a constant u is y = u.
            let mut s2 = (b2 - a2) * u;
            let mut s1 = (b1 - a1) * u + s2;
            for v in x.iter_mut() {
                let input = *v;
                let y = b0 * input + s1;
                s1 = b1 * input - a1 * y + s2;
                s2 = b2 * input - a2 * y;
                *v = y;
            }
        }
    }

    /// The sections' coefficients, `[b0, b1, b2, a1, a2]` each (`a0 = 1`).
    #[doc(hidden)] // For the tests' comparison with SciPy's transfer function.
    #[must_use]
    pub fn sections(&self) -> &[[f64; 5]] {
        &self.sections
    }
}
