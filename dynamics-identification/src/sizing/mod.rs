//! Actuator sizing along a trajectory: per joint, the peak and RMS of
//! `τ = M_links q̈ + C q̇ + g + I_a q̈ + τ_f` (torque, or force for a prismatic joint), the peak
//! mechanical power `τ q̇`, and the five terms at the peak.
//!
//! The RMS is over time, by the trapezoidal rule on `τ²` (samples need not be evenly spaced);
//! each peak is the sample of largest magnitude. Samples are consumed one at a time; each
//! sample's values can also go to a [`Series`] (the figure of `dynamics size --svg`).
//!
//! The terms themselves, four samples at a time, are [`terms`].

pub mod terms;

use crate::lanes::LANES;
use crate::trajectory::Sample;
use dynamics_codegen::model::JointKind;
use terms::{At, Terms, TermsTape};

/// The names of the terms of τ, in the order [`Terms`] lists them.
pub const TERMS: [&str; 5] = ["inertial", "coriolis", "gravity", "actuator", "friction"];

/// Values per joint that a [`Series`] receives for each sample: τ, its five terms (in the order
/// of [`TERMS`]), the power.
pub const SERIES: usize = 7;

/// What receives each sample's values besides the sizing's report, e.g. a decimation for a
/// figure.
pub trait Series {
    /// The sample at time `t`: [`SERIES`] values per joint, joint after joint.
    fn push(&mut self, t: f64, values: &[f64]);
}

/// No series kept.
impl Series for () {
    fn push(&mut self, _: f64, _: &[f64]) {}
}

/// A series kept or not.
impl<S: Series> Series for Option<S> {
    fn push(&mut self, t: f64, values: &[f64]) {
        if let Some(series) = self {
            series.push(t, values);
        }
    }
}

/// What one joint needs.
#[derive(Clone, Debug, Default)]
pub struct JointReport {
    /// τ at its largest magnitude, and when.
    pub peak: f64,
    pub peak_time: f64,
    /// The five terms at that sample, in the order of [`TERMS`].
    pub terms_at_peak: [f64; 5],
    pub rms: f64,
    /// `τ q̇` at its largest magnitude, and when.
    pub peak_power: f64,
    pub peak_power_time: f64,
    /// `∫ τ² dt` so far, and the previous sample's `(t, τ²)`.
    integral: f64,
    previous: Option<(f64, f64)>,
}

/// The sizing of a robot as samples arrive (their terms evaluated [`LANES`] at a time: call
/// [`Sizer::finish`] after the last), each sample's values also pushed to `series`.
pub struct Sizer<'a, S: Series = ()> {
    terms: &'a mut TermsTape,
    /// The samples waiting for a group of [`LANES`], and how many.
    waiting: Vec<Sample>,
    filled: usize,
    pub joints: Vec<JointReport>,
    pub samples: usize,
    pub start: f64,
    pub end: f64,
    pub series: S,
    /// The first sample whose τ² or power is not a finite number: its line and time.
    pub non_finite: Option<(usize, f64, (usize, String, f64))>,
    values: Vec<f64>,
}

impl<'a, S: Series> Sizer<'a, S> {
    /// A sizing of `n` joints whose samples' values also go to `series`.
    #[must_use]
    pub fn new(terms: &'a mut TermsTape, n: usize, series: S) -> Sizer<'a, S> {
        Sizer {
            terms,
            waiting: Vec::with_capacity(LANES),
            filled: 0,
            joints: vec![JointReport::default(); n],
            samples: 0,
            start: 0.0,
            end: 0.0,
            series,
            non_finite: None,
            values: vec![0.0; SERIES * n],
        }
    }

    /// Adds one sample.
    pub fn push(&mut self, sample: &Sample) {
        match self.waiting.get_mut(self.filled) {
            Some(waiting) => waiting.clone_from(sample),
            None => self.waiting.push(sample.clone()),
        }
        self.filled += 1;
        if self.filled == LANES {
            self.finish();
        }
    }

    /// Adds the samples still waiting.
    pub fn finish(&mut self) {
        if self.filled == 0 {
            return;
        }
        let waiting = std::mem::take(&mut self.waiting);
        let at: Vec<At> = waiting[..self.filled]
            .iter()
            .map(|s| At {
                q: &s.q,
                qd: &s.qd,
                qdd: &s.qdd,
            })
            .collect();
        for (s, terms) in waiting.iter().zip(self.terms.terms(&at)) {
            let parts = [
                &terms.inertial,
                &terms.coriolis,
                &terms.gravity,
                &terms.actuator,
                &terms.friction,
            ];
            // τ², summed for the RMS, and the power τ q̇.
            let finite = s.qd.iter().enumerate().all(|(j, qd)| {
                let tau: f64 = parts.iter().map(|p| p[j]).sum();
                (tau * tau).is_finite() && (tau * qd).is_finite()
            });
            if !finite && self.non_finite.is_none() {
                self.non_finite = Some((s.line, s.t, s.largest()));
            }
            self.add(s.t, &s.qd, &terms);
        }
        (self.waiting, self.filled) = (waiting, 0);
    }

    /// Adds one sample whose terms are known.
    pub fn add(&mut self, t: f64, qd: &[f64], terms: &Terms) {
        if self.samples == 0 {
            self.start = t;
        }
        self.samples += 1;
        self.end = t;
        let all = [
            &terms.inertial,
            &terms.coriolis,
            &terms.gravity,
            &terms.actuator,
            &terms.friction,
        ];
        for (j, report) in self.joints.iter_mut().enumerate() {
            let parts: [f64; 5] = core::array::from_fn(|k| all[k][j]);
            let tau: f64 = parts.iter().sum();
            let power = tau * qd[j];
            if self.samples == 1 || tau.abs() > report.peak.abs() {
                report.peak = tau;
                report.peak_time = t;
                report.terms_at_peak = parts;
            }
            if self.samples == 1 || power.abs() > report.peak_power.abs() {
                report.peak_power = power;
                report.peak_power_time = t;
            }
            let square = tau * tau;
            match report.previous {
                Some((t0, s0)) => {
                    report.integral += 0.5 * (s0 + square) * (t - t0);
                    report.rms = (report.integral / (t - self.start)).sqrt();
                }
                None => report.rms = tau.abs(),
            }
            report.previous = Some((t, square));
            let v = &mut self.values[SERIES * j..SERIES * (j + 1)];
            v[0] = tau;
            v[1..6].copy_from_slice(&parts);
            v[6] = power;
        }
        self.series.push(t, &self.values);
    }
}

/// `N m` or `N`.
#[must_use]
pub fn unit(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "N m",
        JointKind::Prismatic => "N",
    }
}
