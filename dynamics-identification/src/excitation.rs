//! An exciting motion for a robot: its period sampled, the search run, the motion found.

use crate::excite::design::{Design, Problem};
use crate::excite::fourier::{Grid, Limits, State};
use crate::{Error, Regressor};

/// The motion's form: its period, the harmonics of its Fourier series, the rate of its samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// In s.
    pub period: f64,
    pub harmonics: usize,
    /// Samples per second.
    pub rate: f64,
}

impl Default for Motion {
    /// `dynamics excite`'s: a period of 10 s, 5 harmonics, 100 samples a second.
    fn default() -> Motion {
        Motion {
            period: 10.0,
            harmonics: 5,
            rate: 100.0,
        }
    }
}

impl Motion {
    /// The fewest samples per period: eight per period of the highest harmonic.
    pub const SAMPLES_PER_HARMONIC: usize = 8;

    /// The most samples per period: its table of sines and cosines is held (16 bytes a
    /// sample).
    pub const MAX_SAMPLES: f64 = 1e7;

    /// The search's problem for `regressor` within `limits` (one per joint).
    ///
    /// # Errors
    /// [`Error::Setting`]: fewer samples per period than eight per period of the highest
    /// harmonic, or more than 10⁷.
    pub fn problem<'r>(
        &self,
        regressor: &'r Regressor,
        limits: Vec<Limits>,
    ) -> Result<Problem<'r>, Error> {
        let samples = (self.period * self.rate).round();
        let fewest = (Motion::SAMPLES_PER_HARMONIC * self.harmonics) as f64;
        if !(fewest..=Motion::MAX_SAMPLES).contains(&samples) {
            return Err(Error::Setting(format!(
                "--period × --rate: {samples} samples per period; between {fewest} (eight per \
                 period of the highest harmonic) and 10⁷"
            )));
        }
        Ok(Problem {
            model: regressor.model(),
            grid: Grid::new(self.period, self.harmonics, samples as usize),
            limits,
        })
    }
}

/// What [`excite()`] found.
pub struct Excited {
    /// The motion, and the condition numbers of it and of the first one tried.
    pub design: Design,
    /// The samples of a period.
    pub grid: Grid,
}

impl Excited {
    /// Every joint's position, velocity and acceleration at sample `k` (`k / samples` periods
    /// from the start; any `k`, the motion being periodic).
    #[must_use]
    pub fn states(&self, k: usize) -> Vec<State> {
        self.design
            .series
            .iter()
            .map(|s| self.grid.state(s, k))
            .collect()
    }

    /// The time of sample `k`, in s: whole periods exactly, then the steps within one (no
    /// drift over many periods).
    #[must_use]
    pub fn time(&self, k: usize) -> f64 {
        let (m, period) = (self.grid.samples(), self.grid.period);
        (k / m) as f64 * period + (k % m) as f64 * period / m as f64
    }
}

/// The motion of `motion`'s form within `limits` (one per joint) whose stacked base regressor
/// has the lowest condition number the search finds from `seed` in at most `evaluations`
/// evaluations; `progress` told the count of evaluations after each.
///
/// # Errors
/// [`Error::Setting`]: as [`Motion::problem`]; [`Error::NoMotion`]: the search found none.
pub fn excite(
    regressor: &Regressor,
    limits: Vec<Limits>,
    motion: &Motion,
    seed: u64,
    evaluations: usize,
    progress: impl FnMut(usize),
) -> Result<Excited, Error> {
    let problem = motion.problem(regressor, limits)?;
    let design = problem.design(seed, evaluations, progress);
    if design.series.is_empty() {
        return Err(Error::NoMotion);
    }
    Ok(Excited {
        design,
        grid: problem.grid,
    })
}
