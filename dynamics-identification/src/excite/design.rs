//! The exciting motion of a robot: the search's variables decoded into every joint's series,
//! and the condition number of the base regressor over a period as the cost.
//!
//! For n joints and L harmonics the search has `n (2(L − 1) + 1)` variables in `[−1, 1]`: per
//! joint the coefficients `a_2..a_L, b_2..b_L` of a series at rest at t = 0, and its placement in
//! the joint's range ([`Grid::fit`] scales the series to the joint's limits, so that any point
//! of the box is a motion within them). The cost is `cond(Y_B)` over [`SEARCH_SAMPLES`] samples
//! of the period, evenly spread among those written ([`Gram`]); the result is judged over all
//! of the period's samples, a chunk at a time ([`Factor`]).

use super::condition::{Factor, Gram};
use super::fourier::{Grid, Limits, Series, State};
use super::search::{minimise, Outcome};
use crate::identify::model::JointValues;
use crate::identify::model::LinearModel;

/// The samples of a period over which the search evaluates the condition number: enough rows
/// (n per sample) for any robot's base parameters many times over, few enough to be cheap.
pub const SEARCH_SAMPLES: usize = 100;

/// The samples whose rows are held at once when the condition number is judged.
const CHUNK: usize = 4096;

/// What the search is given.
pub struct Problem<'a> {
    pub model: &'a LinearModel,
    pub grid: Grid,
    pub limits: Vec<Limits>,
}

/// The motion found, and how it compares with the first one tried.
pub struct Design {
    pub series: Vec<Series>,
    /// `cond(Y_B)` over every sample of the period, of each.
    pub condition: f64,
    pub initial_condition: f64,
    pub outcome: Outcome,
}

impl Problem<'_> {
    /// The search's variables per joint.
    fn per_joint(&self) -> usize {
        self.grid.free() + 1
    }

    /// Every joint's series for the point `x` of the box; `None` if a joint would not move.
    #[must_use]
    pub fn decode(&self, x: &[f64]) -> Option<Vec<Series>> {
        let width = self.per_joint();
        x.chunks(width)
            .zip(&self.limits)
            .map(|(v, limits)| {
                let (free, placement) = v.split_at(width - 1);
                self.grid.fit(free, limits, placement[0])
            })
            .collect()
    }

    /// The states of every joint at sample k.
    #[must_use]
    pub fn states(&self, series: &[Series], k: usize) -> Vec<State> {
        series.iter().map(|s| self.grid.state(s, k)).collect()
    }

    /// `cond(Y_B)` over the samples `ks`, by the Gram matrix.
    #[doc(hidden)] // For the test of the search's cost against the condition number reported.
    pub fn condition(&self, gram: &mut Gram, series: &[Series], ks: &[usize]) -> f64 {
        gram.clear();
        let rows = self.rows(series, ks.iter().copied());
        gram.push(&states(&rows));
        gram.condition()
    }

    /// `cond(Y_B)` over every sample of the period, from the regressor's factor.
    #[must_use]
    pub fn accurate_condition(&self, series: &[Series]) -> f64 {
        let (m, mut factor) = (self.grid.samples(), Factor::new(self.model));
        // A chunk of samples at a time: a period may have millions.
        for start in (0..m).step_by(CHUNK) {
            let rows = self.rows(series, start..m.min(start + CHUNK));
            factor.push(&states(&rows));
        }
        factor.condition()
    }

    /// Positions, velocities and accelerations of every joint at the samples `ks`.
    fn rows(&self, series: &[Series], ks: impl Iterator<Item = usize>) -> Vec<[Vec<f64>; 3]> {
        ks.map(|k| {
            let states = self.states(series, k);
            [
                states.iter().map(|s| s.q).collect(),
                states.iter().map(|s| s.qd).collect(),
                states.iter().map(|s| s.qdd).collect(),
            ]
        })
        .collect()
    }

    /// The search for the motion of lowest condition number, from `seed`, with at most
    /// `evaluations` evaluations, `progress` told the count after each.
    #[must_use]
    pub fn design(&self, seed: u64, evaluations: usize, mut progress: impl FnMut(usize)) -> Design {
        let m = self.grid.samples();
        let count = SEARCH_SAMPLES.min(m);
        let ks: Vec<usize> = (0..count).map(|j| j * m / count).collect();
        let mut gram = Gram::new(self.model);
        let dimension = self.per_joint() * self.limits.len();
        let mut done = 0;
        let outcome = minimise(dimension, seed, evaluations, |x| {
            done += 1;
            progress(done);
            match self.decode(x) {
                Some(series) => self.condition(&mut gram, &series, &ks),
                None => f64::INFINITY,
            }
        });
        // Every point of the box decodes but a measure-zero set; these were evaluated.
        let decode = |x: &[f64]| self.decode(x).unwrap_or_default();
        let (series, initial) = (decode(&outcome.best.0), decode(&outcome.initial.0));
        let judge = |s: &[Series]| {
            if s.is_empty() {
                f64::INFINITY
            } else {
                self.accurate_condition(s)
            }
        };
        Design {
            condition: judge(&series),
            initial_condition: judge(&initial),
            series,
            outcome,
        }
    }
}

/// The states of `rows`, borrowed.
fn states(rows: &[[Vec<f64>; 3]]) -> Vec<JointValues<'_>> {
    rows.iter()
        .map(|[q, qd, qdd]| JointValues { q, qd, qdd })
        .collect()
}
