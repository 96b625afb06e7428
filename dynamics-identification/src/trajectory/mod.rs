//! Trajectories as streams of samples `(t, q, q̇, q̈)`, with the joint torques τ where the file
//! gives them: read from a CSV file, or a built-in quintic point-to-point move.
//!
//! **CSV** ([`read_csv`], [`read_rows`]). A header line names the columns: `t,q1,..,qn`, then
//! optionally `qd1,..,qdn`, then optionally `qdd1,..,qddn`, then, for `dynamics identify`,
//! `tau1,..,taun` (t in s; q in rad or m; τ in N m or N). Blank lines and lines starting with
//! `#` are skipped; every other line holds as many finite numbers as the header, with t strictly
//! increasing. A byte-order mark before the header and `\r\n` line ends are accepted.
//!
//! **Missing derivatives** ([`Differences`]) come from the quadratic through three neighbouring
//! samples. Only three samples are held at once, so a file of any length streams.
//!
//! **Quintic move** ([`quintic()`]).

mod csv;
mod differences;
mod quintic;

pub use csv::{decimal, read_rows, Base, Columns, CsvError, Given, LONGEST_LINE};
pub use differences::{unit_quaternion, Differences, QUATERNION_NORM};
pub use quintic::quintic;
use std::io::BufRead;

/// One sample of a trajectory.
#[derive(Clone, Debug, Default)]
pub struct Sample {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// The joint torques, where the file gives them; else empty.
    pub tau: Vec<f64>,
    /// The file's line of the sample (1-based); 0 for a sample of no file.
    pub line: usize,
    /// The file's columns: which derivatives are its own, not differences.
    pub given: Given,
}

impl Sample {
    /// The value of largest magnitude, as the file's column (1-based) and name it is or is
    /// taken from (q̇ by differences of q: q's column), and the value: where to look when the
    /// equations of a sample overflow. A floating base's `v`, `a` (more than q has) are
    /// named as such, and its torques are the file's last columns.
    #[must_use]
    pub fn largest(&self) -> (usize, String, f64) {
        let (nq, nv) = (self.q.len(), self.qd.len());
        let names = if nq == nv {
            ["q", "qd", "qdd"]
        } else {
            ["q", "v", "a"]
        };
        let groups = self.given.groups();
        // The first column of each group, and of the torques after the given groups.
        let starts = [2, 2 + nq, 2 + nq + nv, 2 + nq + (groups - 1) * nv];
        let values = [&self.q, &self.qd, &self.qdd, &self.tau];
        let mut best = (1, "t".to_string(), self.t);
        for (g, values) in values.iter().enumerate() {
            // A derivative the file does not give is its lower derivative's differences.
            let own = if g == 3 { g } else { g.min(groups - 1) };
            let (name, first) = if g == 3 {
                ("tau", nv + 1 - self.tau.len())
            } else {
                (names[own], 1)
            };
            for (j, &x) in values.iter().enumerate() {
                // A NaN, else the larger: the first of equals.
                if x.is_nan() || x.abs() > best.2.abs() {
                    // q̇ of a floating base by differences: its joint's q, or the base's first.
                    let j = if own == 0 && g > 0 && nq > nv {
                        j.saturating_sub(6) + usize::from(j >= 6) * 7
                    } else {
                        j
                    };
                    best = (starts[own] + j, format!("{name}{}", first + j), x);
                }
            }
        }
        best
    }
}

/// Reads the trajectory of a robot from `reader`, with the columns `columns`, calling `each` on
/// every sample in order, and `progress` with the count of bytes read every so often; the
/// number of samples and how their derivatives were had.
///
/// # Errors
/// The first bad line, fewer than three samples where derivatives must be estimated, or a
/// derivative that is not finite.
pub fn read_csv(
    reader: impl BufRead,
    columns: Columns,
    mut each: impl FnMut(&Sample),
    progress: impl FnMut(u64),
) -> Result<(usize, &'static str), CsvError> {
    let mut differences = Differences::new(columns);
    let rows = read_rows(
        reader,
        columns,
        |line, given, row| differences.push(line, given, row, &mut each),
        progress,
    )?;
    let count = differences.finish(rows.last_line, &mut each)?;
    Ok((count, differences.method()))
}
