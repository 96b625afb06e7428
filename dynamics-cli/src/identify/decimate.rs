//! Parallel filtering and decimation (Gautier, 1997): the measured torques and every column of
//! the regressor pass the same linear filter, then one sample in `d` is kept.
//!
//! **The same filter on both sides.** For any linear filter F, `τ = Y π` gives
//! `F(τ) = F(Y) π` exactly, whatever is in τ and Y above the filter's band: a Coulomb column
//! `sign(q̇)` keeps its steps in Y as in τ, and both are smoothed alike. (Filtering τ alone would
//! smooth its steps while the model's `sign(q̇)` stays sharp.)
//!
//! **Decimation.** The filtered signals have nothing above the filter's band, but neighbouring
//! samples are not independent: the noise left is band-limited, so residuals are correlated over
//! about `d` samples and least squares, which takes them as independent, would report standard
//! deviations about `√d` times too small. Keeping one sample in `d`, at the filter's band's
//! Nyquist rate, makes them nearly independent again.
//!
//! **The filter** is a zero-phase FIR low-pass, so that it streams (an IIR run forward and
//! backward needs every sample of every column at once): the ideal low-pass of cutoff
//! `1/(2d)` cycles per sample (the kept samples' Nyquist frequency),
//! `h_k = sin(π k / d) / (π k)`, `|k| ≤ 8d`, times a Hamming window
//! `0.54 + 0.46 cos(π k / 8d)`, scaled to a DC gain of 1: within 0.4 % of 1 up to 0.75 of the
//! cutoff, −6 dB at it, and at least 47 dB down from 1.2 of it (a transition about
//! `3.3 / (16d + 1)` cycles per sample wide). The first and last `8d` samples, where the window
//! is incomplete, give no output.

/// The number of taps of the decimating low-pass for a decimation `d`: `16d + 1`, a window of
/// eight kept samples on either side of the middle one.
#[must_use]
pub fn length(d: usize) -> usize {
    16 * d + 1
}

/// Taps of the decimating low-pass for a decimation `d`: [`length`]`(d)` of them, symmetric.
#[must_use]
pub fn taps(d: usize) -> Vec<f64> {
    let half = length(d) / 2;
    let (dd, m) = (d as f64, half as f64);
    let raw: Vec<f64> = (0..=2 * half)
        .map(|i| {
            let k = i as f64 - m;
            let ideal = if k == 0.0 {
                1.0 / dd
            } else {
                (std::f64::consts::PI * k / dd).sin() / (std::f64::consts::PI * k)
            };
            ideal * (0.54 + 0.46 * (std::f64::consts::PI * k / m).cos())
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    raw.into_iter().map(|h| h / sum).collect()
}

/// The filter and decimation over rows of a fixed width, as they stream.
#[derive(Clone, Debug)]
pub struct Decimator {
    taps: Vec<f64>,
    decimation: usize,
    width: usize,
    /// The last `taps.len()` rows, a ring, row-major; and their times.
    rows: Vec<f64>,
    times: Vec<f64>,
    /// Rows taken so far.
    count: usize,
    out: Vec<f64>,
}

impl Decimator {
    /// For rows of `width` values, keeping one filtered row in `decimation`.
    #[must_use]
    pub fn new(decimation: usize, width: usize) -> Decimator {
        let taps = taps(decimation.max(1));
        let length = taps.len();
        Decimator {
            taps,
            decimation: decimation.max(1),
            width,
            rows: vec![0.0; length * width],
            times: vec![0.0; length],
            count: 0,
            out: vec![0.0; width],
        }
    }

    /// Takes the row of time `t`; at every `d`-th complete window, the filtered row of the
    /// window's middle sample and its time.
    pub fn push(&mut self, t: f64, row: &[f64]) -> Option<(f64, &[f64])> {
        let (length, w) = (self.taps.len(), self.width);
        let slot = self.count % length;
        self.rows[slot * w..(slot + 1) * w].copy_from_slice(row);
        self.times[slot] = t;
        self.count += 1;
        if self.count < length || (self.count - length) % self.decimation != 0 {
            return None;
        }
        self.out.fill(0.0);
        // The oldest row is the slot after the newest; the taps are symmetric, so their order
        // along the window does not matter.
        for (j, h) in self.taps.iter().enumerate() {
            let s = (self.count + j) % length;
            for (o, x) in self.out.iter_mut().zip(&self.rows[s * w..(s + 1) * w]) {
                *o += h * x;
            }
        }
        let middle = (self.count + length / 2) % length;
        Some((self.times[middle], &self.out))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The filter's gain at `f` cycles per sample.
    fn gain(taps: &[f64], f: f64) -> f64 {
        let m = (taps.len() / 2) as f64;
        taps.iter()
            .enumerate()
            .map(|(i, h)| h * (2.0 * PI * f * (i as f64 - m)).cos())
            .sum()
    }

    #[test]
    fn the_low_pass_passes_below_the_kept_nyquist_and_stops_above() {
        for d in [1, 4, 20] {
            let h = taps(d);
            assert_eq!(h.len(), 16 * d + 1);
            assert!((h.iter().sum::<f64>() - 1.0).abs() < 1e-14);
            let nyquist = 0.5 / d as f64;
            if d > 1 {
                // Within 0.4 % of 1 to 0.75 of the cutoff, half at it, 47 dB down past 1.2 of it.
                for f in [0.0, 0.25, 0.5, 0.7, 0.75] {
                    assert!((gain(&h, f * nyquist) - 1.0).abs() < 4e-3, "{d} {f}");
                }
                assert!((gain(&h, nyquist) - 0.5).abs() < 0.01, "{d}");
                for f in [1.2, 1.25, 1.5, 2.0, 3.0] {
                    assert!(gain(&h, f * nyquist).abs() < 4.5e-3, "{d} {f}");
                }
            } else {
                // d = 1: the ideal low-pass at the Nyquist frequency is the identity.
                assert!((h[8] - 1.0).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn rows_are_filtered_alike_and_one_in_d_is_kept_at_the_window_middle() {
        let d = 3;
        let mut decimator = Decimator::new(d, 2);
        let mut kept = Vec::new();
        for k in 0..200 {
            let t = f64::from(k);
            // A slow sinusoid passes unshifted (zero phase); a constant passes unchanged.
            let row = [(2.0 * PI * 0.02 * t).sin(), 5.0];
            if let Some((t, out)) = decimator.push(t, &row) {
                kept.push((t, out.to_vec()));
            }
        }
        // Windows of 49 rows: the first complete at row 48, middle 24; then every third.
        assert_eq!(kept.len(), (200 - 49) / 3 + 1);
        assert_eq!(kept[0].0, 24.0);
        assert_eq!(kept[1].0, 27.0);
        for (t, out) in &kept {
            let want = gain(&taps(d), 0.02) * (2.0 * PI * 0.02 * t).sin();
            assert!((out[0] - want).abs() < 1e-12, "{t}");
            assert!((out[1] - 5.0).abs() < 1e-12);
        }
    }
}
