//! The exciting motion of one joint: a finite Fourier series (Swevers, Ganseman, Tükel, De
//! Schutter and Van Brussel, *Optimal robot excitation and identification*, IEEE Trans. Robotics
//! and Automation 13(5), 1997), with base pulsation `ω = 2π / T` and L harmonics:
//!
//! ```text
//! q(t)   = q₀ + Σ_{l=1..L} (a_l / (ω l)) sin(ω l t) − (b_l / (ω l)) cos(ω l t)
//! q̇(t)   =      Σ_{l=1..L}  a_l cos(ω l t) + b_l sin(ω l t)
//! q̈(t)   =      Σ_{l=1..L}  ω l (b_l cos(ω l t) − a_l sin(ω l t))
//! ```
//!
//! The motion is periodic, so a controller can repeat it and the measurements of the periods
//! be averaged. It starts (and so ends each period) **at rest**: `q̇(0) = Σ a_l = 0` and
//! `q̈(0) = ω Σ l b_l = 0`, so that the robot can be brought to `q(0)` and the series started
//! there. The search varies the coefficients of the harmonics 2..L; the first harmonic's are
//! set by these two constraints, `a_1 = −Σ_{l≥2} a_l`, `b_1 = −Σ_{l≥2} l b_l`.
//!
//! **Limits by scaling.** The series is linear in `(a, b)`: multiplied by k, the motion about
//! q₀ and its derivatives are multiplied by k. The largest k whose motion's range, speed and
//! acceleration, over the samples of a period, stay within the joint's is taken, and `q₀`
//! places the range in the joint's by a placement `p ∈ [−1, 1]` (−1: at the lower limit, 0:
//! centred, 1: at the upper). So every candidate of the search meets the limits at every
//! sample, and moves as far as they allow. The samples are `t_k = k T / M`: at sample k the
//! harmonic l has the phase `2π ((l k) mod M) / M`, read from one table, so that each period's
//! samples are bit for bit the first's.

/// A joint's limits: the range of its variable (rad or m), its largest speed and acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    pub lower: f64,
    pub upper: f64,
    pub velocity: f64,
    pub acceleration: f64,
}

/// A fraction of each limit kept free, so that the rounding of `q₀ + k s(t)` cannot cross it.
const MARGIN: f64 = 1e-9;

/// The samples of one period and the sines and cosines of their phases.
#[derive(Clone, Debug)]
pub struct Grid {
    pub period: f64,
    pub harmonics: usize,
    /// `sin` and `cos` of `2π j / M`, j = 0..M.
    table: Vec<(f64, f64)>,
}

/// One joint's series: `q₀` and the coefficients `a_l`, `b_l` (rad/s or m/s), l = 1..L.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub q0: f64,
    pub a: Vec<f64>,
    pub b: Vec<f64>,
}

/// The state of one joint at a sample.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State {
    pub q: f64,
    pub qd: f64,
    pub qdd: f64,
}

impl Grid {
    /// `samples` samples per period of `period` s, L = `harmonics`.
    ///
    /// # Panics
    /// Fewer samples than harmonics: a period must hold more samples than the highest
    /// harmonic's cycles.
    #[must_use]
    pub fn new(period: f64, harmonics: usize, samples: usize) -> Grid {
        assert!(
            samples > harmonics,
            "{samples} samples for {harmonics} harmonics"
        );
        let step = std::f64::consts::TAU / samples as f64;
        let table = (0..samples).map(|j| (j as f64 * step).sin_cos()).collect();
        Grid {
            period,
            harmonics,
            table,
        }
    }

    /// The samples per period, M.
    #[must_use]
    pub fn samples(&self) -> usize {
        self.table.len()
    }

    /// The base pulsation ω, rad/s.
    #[must_use]
    pub fn omega(&self) -> f64 {
        std::f64::consts::TAU / self.period
    }

    /// The free coefficients per joint: `a_l`, `b_l` for l = 2..L.
    #[must_use]
    pub fn free(&self) -> usize {
        2 * (self.harmonics - 1)
    }

    /// The series at rest at t = 0 whose harmonics 2..L have the coefficients `free` (`a_2..a_L`
    /// then `b_2..b_L`), about q₀ = 0.
    #[must_use]
    pub fn at_rest(&self, free: &[f64]) -> Series {
        let (rest_a, rest_b) = free.split_at(self.harmonics - 1);
        let mut a = vec![-rest_a.iter().sum::<f64>()];
        a.extend(rest_a);
        let weighted: f64 = rest_b.iter().zip(2..).map(|(b, l)| b * f64::from(l)).sum();
        let mut b = vec![-weighted];
        b.extend(rest_b);
        Series { q0: 0.0, a, b }
    }

    /// The state of `series` at sample k (of any period).
    ///
    /// The first harmonic is added last, and ω (1/ω) factored out of q̈ (q): a series at rest
    /// has `a_1 = −Σ_{l≥2} a_l` and `b_1 = −Σ_{l≥2} l b_l` summed in the same order, so that at
    /// t = 0 the sums cancel exactly and q̇ = q̈ = 0, not a rounding residue whose sign Coulomb
    /// friction would read.
    #[must_use]
    pub fn state(&self, series: &Series, k: usize) -> State {
        let m = self.samples();
        self.evaluate(series, |l| (l % m) * (k % m) % m)
    }

    /// The state of `series` where harmonic l has the phase of table entry `phase(l)`.
    fn evaluate(&self, series: &Series, phase: impl Fn(usize) -> usize) -> State {
        let (mut q, mut qd, mut qdd) = (0.0, 0.0, 0.0);
        let harmonics = series.a.len();
        for l in (2..=harmonics).chain([1]) {
            let (a, b) = (series.a[l - 1], series.b[l - 1]);
            let (sin, cos) = self.table[phase(l)];
            let l = l as f64;
            q += (a * sin - b * cos) / l;
            qd += a * cos + b * sin;
            qdd += l * b * cos - l * a * sin;
        }
        let omega = self.omega();
        State {
            q: series.q0 + q / omega,
            qd,
            qdd: omega * qdd,
        }
    }

    /// The series at rest with the free coefficients `free`, scaled to move as far as
    /// `limits` allow over the period's samples and placed by `placement` (clamped to
    /// [−1, 1]); `None` for a series that does not move.
    #[must_use]
    pub fn fit(&self, free: &[f64], limits: &Limits, placement: f64) -> Option<Series> {
        let shape = self.at_rest(free);
        let (mut low, mut high, mut speed, mut acceleration) = (f64::MAX, f64::MIN, 0.0, 0.0);
        // The phases of sample k, (l k) mod M, advanced by l per sample: the states are
        // those `state` gives, without its divisions.
        let m = self.samples();
        let mut phases = vec![0; self.harmonics + 1];
        for _ in 0..m {
            let s = self.evaluate(&shape, |l| phases[l]);
            for (l, phase) in phases.iter_mut().enumerate() {
                // l < M (eight samples per period of the highest harmonic at least).
                *phase += l;
                if *phase >= m {
                    *phase -= m;
                }
            }
            low = low.min(s.q);
            high = high.max(s.q);
            speed = f64::max(speed, s.qd.abs());
            acceleration = f64::max(acceleration, s.qdd.abs());
        }
        let keep = 1.0 - MARGIN;
        let range = (limits.upper - limits.lower) * keep;
        let scale = [
            range / (high - low),
            limits.velocity * keep / speed,
            limits.acceleration * keep / acceleration,
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
        if !scale.is_finite() || scale <= 0.0 {
            return None;
        }
        let slack = range - scale * (high - low);
        let lowest = limits.lower + 0.5 * MARGIN * (limits.upper - limits.lower);
        let start = lowest + 0.5 * (placement.clamp(-1.0, 1.0) + 1.0) * slack;
        // The first harmonic's coefficients from the scaled others: at rest exactly.
        let scaled: Vec<f64> = free.iter().map(|c| c * scale).collect();
        Some(Series {
            q0: start - scale * low,
            ..self.at_rest(&scaled)
        })
    }
}
