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
//! is incomplete, give no output. The outputs are accumulated as the rows stream past, so that
//! the memory held is 17 rows whatever d ([`Decimator`]); the taps, `16d + 1` numbers, are
//! bounded by the samples of the file (`identify::source` refuses a window longer than it).

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
///
/// Output m is the window of rows `m d ..= m d + 16d`; a row belongs to the windows of at most
/// `OPEN` outputs, each accumulated as its rows arrive (in their order, as a window held
/// whole would be summed). So the memory is `OPEN` rows whatever d, not a window of `16d + 1`.
#[derive(Clone, Debug)]
pub struct Decimator {
    taps: Vec<f64>,
    decimation: usize,
    /// The sums of the open outputs, output m in slot `m % OPEN`, row-major; each one's time.
    sums: Vec<f64>,
    times: Vec<f64>,
    width: usize,
    /// Rows taken so far.
    count: usize,
}

/// The outputs a row can belong to: windows of `16d + 1` rows start every d rows.
pub const OPEN: usize = 17;

impl Decimator {
    /// For rows of `width` values, keeping one filtered row in `decimation`.
    #[must_use]
    pub fn new(decimation: usize, width: usize) -> Decimator {
        Decimator {
            taps: taps(decimation.max(1)),
            decimation: decimation.max(1),
            sums: vec![0.0; OPEN * width],
            times: vec![0.0; OPEN],
            width,
            count: 0,
        }
    }

    /// The values held: `OPEN` sums of a row's width.
    #[doc(hidden)] // For the tests of the memory held.
    #[must_use]
    pub fn held(&self) -> usize {
        self.sums.len()
    }

    /// Takes the row of time `t`; at every `d`-th complete window, the filtered row of the
    /// window's middle sample and its time.
    pub fn push(&mut self, t: f64, row: &[f64]) -> Option<(f64, &[f64])> {
        let (d, w, k) = (self.decimation, self.width, self.count);
        let last = self.taps.len() - 1;
        self.count += 1;
        // The outputs m with m d ≤ k ≤ m d + 16d, oldest first.
        let newest = k / d;
        let oldest = k.saturating_sub(last).div_ceil(d);
        for m in oldest..=newest {
            let slot = m % OPEN;
            let sum = &mut self.sums[slot * w..(slot + 1) * w];
            let offset = k - m * d;
            if offset == 0 {
                sum.fill(0.0);
            }
            if offset == last / 2 {
                self.times[slot] = t;
            }
            let h = self.taps[offset];
            for (s, x) in sum.iter_mut().zip(row) {
                *s += h * x;
            }
        }
        // Row k ends output `oldest`'s window when it is its last row.
        if k < last || (k - last) % d != 0 {
            return None;
        }
        let slot = oldest % OPEN;
        Some((self.times[slot], &self.sums[slot * w..(slot + 1) * w]))
    }
}
