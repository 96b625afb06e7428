//! The measured samples, replayable: streamed from the CSV file each time (nothing held), or,
//! with a low-pass filter, held once in memory (a zero-phase filter needs the whole signal), the
//! positions (and any given velocities and accelerations) filtered before the derivatives are
//! taken. The torques are left as measured here: they are filtered alike with the regressor's
//! columns, and decimated ([`super::decimate`]).

use super::decimate;
use super::filter::LowPass;
use crate::trajectory::{self, Base, Columns, CsvError, Differences, Given, Sample};
use crate::Error;
use std::io::BufReader;

/// Steps may differ from the mean step by this fraction for the filter's design to hold.
const EVEN: f64 = 0.05;

/// Where the samples come from.
pub enum Source {
    File {
        path: String,
        columns: Columns,
    },
    Filtered {
        path: String,
        columns: Columns,
        given: Given,
        /// The file's columns (t first), filtered (but t).
        data: Vec<Vec<f64>>,
        /// The file's line of each sample.
        lines: Vec<usize>,
        last_line: usize,
        filter: Filter,
    },
}

/// The filter applied, for the report.
#[derive(Clone, Copy, Debug)]
pub struct Filter {
    pub cutoff: f64,
    pub rate: f64,
    /// One sample in this many is kept.
    pub decimation: usize,
    /// The samples of the file.
    pub read: usize,
}

impl Filter {
    /// The samples the decimation keeps: one in `d` once a window of `16d + 1` is full.
    #[must_use]
    pub fn kept(&self) -> usize {
        let window = decimate::length(self.decimation);
        if self.read < window {
            0
        } else {
            (self.read - window) / self.decimation + 1
        }
    }
}

impl Source {
    /// The samples of the file at `path`, filtered at `cutoff` Hz if given.
    ///
    /// # Errors
    /// [`Error::Samples`]: the file cannot be read, a bad line, or uneven samples where a
    /// filter is asked for; [`Error::Setting`]: a cutoff the samples' rate or count refuses.
    pub fn open(path: &str, columns: Columns, cutoff: Option<f64>) -> Result<Source, Error> {
        let Some(cutoff) = cutoff else {
            return Ok(Source::File {
                path: path.to_string(),
                columns,
            });
        };
        let floating = columns.base != Base::Fixed;
        let file = std::fs::File::open(path).map_err(|e| Error::Samples(format!("{path}: {e}")))?;
        let (mut data, mut lines): (Vec<Vec<f64>>, Vec<usize>) = (Vec::new(), Vec::new());
        let rows = trajectory::read_rows(
            BufReader::new(file),
            columns,
            |line, _, mut row| {
                if floating {
                    trajectory::unit_quaternion(line, &mut row[QUATERNION])?;
                }
                data.resize(row.len(), Vec::new());
                for (column, x) in data.iter_mut().zip(row) {
                    column.push(x);
                }
                lines.push(line);
                Ok(())
            },
            |_| {},
        )
        .map_err(|e| Error::Samples(format!("{path}: {e}")))?;
        if data.is_empty() {
            let line = rows.last_line;
            return Err(Error::Samples(format!(
                "{path}: line {line}: no samples after the header"
            )));
        }
        let rate = even_rate(&data[0]).map_err(|(k, message)| {
            let e = CsvError {
                line: lines[k],
                column: Some((1, "t".into())),
                message,
            };
            Error::Samples(format!("{path}: {e}"))
        })?;
        let low_pass = LowPass::butterworth(cutoff, rate)
            .map_err(|e| Error::Setting(format!("--cutoff: {e}")))?;
        let read = data[0].len();
        let decimation = fitting_decimation(path, cutoff, rate, read)?;
        if floating {
            continuous(&mut data[QUATERNION]);
        }
        // Not t, nor the torques at the end.
        let torques = 1 + columns.positions() + (rows.given.groups() - 1) * columns.rates();
        for column in &mut data[1..torques] {
            low_pass.filtfilt(column);
        }
        if floating {
            // Filtered entry by entry, the quaternion leaves the unit sphere by the filter's
            // error: back onto it.
            normalised(&mut data[QUATERNION]);
        }
        Ok(Source::Filtered {
            path: path.to_string(),
            columns,
            given: rows.given,
            data,
            lines,
            last_line: rows.last_line,
            filter: Filter {
                cutoff,
                rate,
                decimation,
                read,
            },
        })
    }

    /// The file's path.
    #[must_use]
    pub fn path(&self) -> &str {
        match self {
            Source::File { path, .. } | Source::Filtered { path, .. } => path,
        }
    }

    /// The filter applied, if any.
    #[must_use]
    pub fn filter(&self) -> Option<Filter> {
        match self {
            Source::File { .. } => None,
            Source::Filtered { filter, .. } => Some(*filter),
        }
    }

    /// Passes every sample to `each`, in order; how q̇ and q̈ were had.
    ///
    /// # Errors
    /// Reading the file (which may have changed since it was first read).
    pub fn each(&self, mut each: impl FnMut(&Sample)) -> Result<&'static str, String> {
        match self {
            Source::File { path, columns } => {
                let file = std::fs::File::open(path).map_err(|e| format!("{path}: {e}"))?;
                let (_, method) =
                    trajectory::read_csv(BufReader::new(file), *columns, each, |_| {})
                        .map_err(|e| format!("{path}: {e}"))?;
                Ok(method)
            }
            Source::Filtered {
                path,
                columns,
                given,
                data,
                lines,
                last_line,
                ..
            } => {
                let mut differences = Differences::new(*columns);
                let at = |e: CsvError| format!("{path}: {e} (after the low-pass filter)");
                for (k, &line) in lines.iter().enumerate() {
                    let row = data.iter().map(|column| column[k]).collect();
                    differences.push(line, *given, row, &mut each).map_err(at)?;
                }
                differences.finish(*last_line, &mut each).map_err(at)?;
                Ok(differences.method())
            }
        }
    }
}

/// A floating base's quaternion `qx, qy, qz, qw`: the columns of `q4..q7`.
const QUATERNION: std::ops::Range<usize> = 4..8;

/// The quaternions of the columns `q` (x, y, z, w) of each sample made continuous: each of the
/// two of a rotation, the one nearer the sample before (a filter across a jump from `q` to `−q`
/// would pass through no rotation at all).
fn continuous(q: &mut [Vec<f64>]) {
    for k in 1..q[0].len() {
        let dot: f64 = q.iter().map(|c| c[k] * c[k - 1]).sum();
        if dot < 0.0 {
            q.iter_mut().for_each(|c| c[k] = -c[k]);
        }
    }
}

/// The quaternions of the columns `q` divided by their norms.
fn normalised(q: &mut [Vec<f64>]) {
    for k in 0..q[0].len() {
        let norm = q.iter().map(|c| c[k] * c[k]).sum::<f64>().sqrt();
        q.iter_mut().for_each(|c| c[k] /= norm);
    }
}

/// One sample in this many is kept at `cutoff` for samples at `rate`: the Butterworth cutoff at
/// 0.8 of the kept samples' Nyquist frequency; at least 1 (a cutoff above 0.4 f_s keeps every
/// sample). A float: a small cutoff asks for more than any `usize`.
fn decimation(cutoff: f64, rate: f64) -> f64 {
    (0.4 * rate / cutoff).floor().max(1.0)
}

/// The decimation at `cutoff`, if the window of its filter, `16d + 1` samples, fits in the
/// `read` samples of `path`; else why not, and the smallest cutoff whose window fits.
fn fitting_decimation(path: &str, cutoff: f64, rate: f64, read: usize) -> Result<usize, Error> {
    let d = decimation(cutoff, rate);
    let window = 16.0 * d + 1.0;
    if window <= read as f64 {
        // At most the file's length: a `usize`.
        return Ok(d as usize);
    }
    let count = |x: f64| {
        if x < 1e15 {
            format!("{x:.0}")
        } else {
            format!("{x:.3e}")
        }
    };
    // Without the hundreds of zeros of a tiny number's decimals.
    let cutoff = trajectory::decimal(cutoff);
    let fits = match (read.max(1) - 1) / 16 {
        0 => "no cutoff does: the shortest window (a cutoff above 0.4 of the sample rate, every \
              sample kept) is 17 samples"
            .to_string(),
        largest => format!(
            "the smallest cutoff whose window fits is {} Hz",
            smallest_cutoff(rate, largest)
        ),
    };
    Err(Error::Setting(format!(
        "--cutoff {cutoff}: for samples at {} Hz its filter keeps one sample in {} and needs a \
         window of {} samples (16 d + 1, d = ⌊0.4 f_s / f_c⌋), more than the {read} samples of \
         {path}: {fits}",
        crate::text::number(rate),
        count(d),
        count(window)
    )))
}

/// The smallest cutoff of three significant digits whose decimation is at most `largest`: the
/// cutoff must exceed `0.4 f_s / (largest + 1)`.
fn smallest_cutoff(rate: f64, largest: usize) -> f64 {
    let bound = 0.4 * rate / (largest + 1) as f64;
    let exponent = bound.log10().floor() as i32 - 2;
    let below = (bound / 10f64.powi(exponent)).floor() as i64;
    // A step or two above the bound rounded down (a finite rate: `even_rate`).
    for mantissa in below..below + 4 {
        // As the user would type it, parsed as the option is.
        let cutoff: f64 = format!("{mantissa}e{exponent}").parse().unwrap_or(bound);
        if decimation(cutoff, rate) <= largest as f64 {
            return cutoff;
        }
    }
    bound * (1.0 + 1e-3)
}

/// The sample rate of evenly spaced times; else the index of the first uneven step and why.
fn even_rate(t: &[f64]) -> Result<f64, (usize, String)> {
    if t.len() < 2 {
        return Err((0, "a filter needs at least two samples".into()));
    }
    let mean = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    if !(1.0 / mean).is_normal() {
        let message = format!(
            "--cutoff needs a sample rate: the mean step {mean:e} s from t = {} s to {} s has none",
            t[0],
            t[t.len() - 1]
        );
        return Err((t.len() - 1, message));
    }
    for k in 1..t.len() {
        let step = t[k] - t[k - 1];
        if (step - mean).abs() > EVEN * mean {
            return Err((
                k,
                format!(
                    "--cutoff needs evenly spaced samples: a step of {step} s where the mean \
                     step is {mean} s"
                ),
            ));
        }
    }
    Ok(1.0 / mean)
}
