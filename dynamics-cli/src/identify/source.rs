//! The measured samples, replayable: streamed from the CSV file each time (nothing held), or,
//! with a low-pass filter, held once in memory (a zero-phase filter needs the whole signal), the
//! positions (and any given velocities and accelerations) filtered before the derivatives are
//! taken. The torques are left as measured here: they are filtered alike with the regressor's
//! columns, and decimated ([`super::decimate`]).

use super::decimate;
use super::filter::{LowPass, ORDER};
use crate::trajectory::{self, Columns, CsvError, Differences, Given, Sample};
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
    /// In words.
    #[must_use]
    pub fn describe(&self) -> String {
        format!(
            "q (and any q̇, q̈ given): {ORDER}th-order Butterworth low-pass at {} Hz (samples \
             at {} Hz), forward and backward (zero phase, −6 dB at the cutoff), before \
             differentiation; τ and every column of the regressor alike: a zero-phase FIR \
             low-pass ({} taps) at {} Hz, then one sample in {} kept, {} of {} (parallel \
             filtering and decimation)",
            self.cutoff,
            crate::plot::number(self.rate),
            decimate::length(self.decimation),
            crate::plot::number(self.rate / (2.0 * self.decimation as f64)),
            self.decimation,
            self.kept(),
            self.read
        )
    }

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
    /// The file cannot be read, a bad line, or uneven samples where a filter is asked for.
    pub fn open(path: &str, columns: Columns, cutoff: Option<f64>) -> Result<Source, String> {
        let Some(cutoff) = cutoff else {
            return Ok(Source::File {
                path: path.to_string(),
                columns,
            });
        };
        let file = std::fs::File::open(path).map_err(|e| format!("{path}: {e}"))?;
        let mut data: Vec<Vec<f64>> = Vec::new();
        let rows = trajectory::read_rows(
            BufReader::new(file),
            columns,
            |_, row| {
                data.resize(row.len(), Vec::new());
                for (column, x) in data.iter_mut().zip(row) {
                    column.push(x);
                }
            },
            |_| {},
        )
        .map_err(|e| format!("{path}: {e}"))?;
        if data.is_empty() {
            let line = rows.last_line;
            return Err(format!("{path}: line {line}: no samples after the header"));
        }
        let rate = even_rate(&data[0]).map_err(|(k, message)| {
            let e = CsvError {
                line: line_of(path, k),
                column: Some((1, "t".into())),
                message,
            };
            format!("{path}: {e}")
        })?;
        let low_pass = LowPass::butterworth(cutoff, rate).map_err(|e| format!("--cutoff: {e}"))?;
        // Not t, nor the torques at the end.
        let torques = data.len() - columns.joints;
        for column in &mut data[1..torques] {
            low_pass.filtfilt(column);
        }
        // The cutoff at 0.8 of the kept samples' Nyquist frequency; at least 1: a cutoff above
        // 0.4 f_s keeps every sample.
        let decimation = ((0.4 * rate / cutoff).floor() as usize).max(1);
        let read = data[0].len();
        Ok(Source::Filtered {
            path: path.to_string(),
            columns,
            given: rows.given,
            data,
            last_line: rows.last_line,
            filter: Filter {
                cutoff,
                rate,
                decimation,
                read,
            },
        })
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
                last_line,
                ..
            } => {
                let mut differences = Differences::new(columns.joints, columns.torques);
                for k in 0..data[0].len() {
                    let row = data.iter().map(|column| column[k]).collect();
                    differences.push(*given, row, &mut each);
                }
                differences
                    .finish(&mut each)
                    .map_err(|message| format!("{path}: line {last_line}: {message}"))?;
                Ok(differences.method())
            }
        }
    }
}

/// The sample rate of evenly spaced times; else the index of the first uneven step and why.
fn even_rate(t: &[f64]) -> Result<f64, (usize, String)> {
    if t.len() < 2 {
        return Err((0, "a filter needs at least two samples".into()));
    }
    let mean = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
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

/// The file line of data row `k` (0-based), counting the header and skipped lines: read again,
/// only on this error's path.
fn line_of(path: &str, k: usize) -> usize {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let data_lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim().starts_with('#'))
        .map(|(i, _)| i + 1);
    // The first such line is the header.
    data_lines.skip(1).nth(k).unwrap_or(0)
}
