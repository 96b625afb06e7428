//! Missing derivatives from the samples: the quadratic through three neighbouring samples
//! (central differences on non-uniform time, second order). At `t_1` between `t_0` and `t_2`,
//! `ẋ_1 = Σ_k L_k'(t_1) x_k` and `ẍ_1 = Σ_k L_k'' x_k` with `L_k` the Lagrange basis of
//! `t_0, t_1, t_2`; the first and the last sample take the same quadratic's derivatives at
//! their own time. q̈ is differentiated from q̇ when the file gives q̇, else from q directly.
//!
//! The weights of a derivative sum to zero, so `Σ_k w_k x_k = Σ_k w_k (x_k − x_1)`: the
//! differences are taken from the middle sample, which gives an exact zero for a joint that does
//! not move (where `Σ w_k x_k` leaves a rounding residue whose sign would be read as Coulomb
//! friction's `sign(q̇)`), and loses no digits to a large constant part of `x`.
//!
//! A derivative that is not finite (time steps so short, or values so large, that the
//! differences overflow) is an error at the sample's line, in the column it was taken of.

use super::csv::{CsvError, Given};
use super::Sample;
use std::collections::VecDeque;

/// The last three rows and their lines, for derivatives by the quadratic through them.
pub struct Differences {
    n: usize,
    rows: VecDeque<(usize, Vec<f64>)>,
    given: Given,
    count: usize,
    sample: Sample,
}

impl Differences {
    /// For `n` joints, with joint torques at the end of each row when `torques`.
    pub fn new(n: usize, torques: bool) -> Differences {
        Differences {
            n,
            rows: VecDeque::with_capacity(3),
            given: Given::Positions,
            count: 0,
            sample: Sample {
                t: 0.0,
                q: vec![0.0; n],
                qd: vec![0.0; n],
                qdd: vec![0.0; n],
                tau: vec![0.0; if torques { n } else { 0 }],
                line: 0,
                given: Given::Positions,
            },
        }
    }

    /// How q̇ and q̈ were had.
    pub fn method(&self) -> &'static str {
        match self.given {
            Given::Positions => "q̇ and q̈ by central differences",
            Given::Velocities => "q̈ by central differences of q̇",
            Given::Accelerations => "q̇ and q̈ given",
        }
    }

    /// Takes the next row (`t`, the columns `given`, the torques if any) of the file's line
    /// `line`, passing to `each` every sample whose derivatives are now known.
    ///
    /// # Errors
    /// A derivative that is not finite.
    pub fn push(
        &mut self,
        line: usize,
        given: Given,
        row: Vec<f64>,
        each: &mut impl FnMut(&Sample),
    ) -> Result<(), CsvError> {
        self.given = given;
        self.count += 1;
        if self.given == Given::Accelerations {
            let n = self.n;
            let s = &mut self.sample;
            (s.t, s.line, s.given) = (row[0], line, given);
            s.q.copy_from_slice(&row[1..=n]);
            s.qd.copy_from_slice(&row[n + 1..=2 * n]);
            s.qdd.copy_from_slice(&row[2 * n + 1..=3 * n]);
            let torques = s.tau.len();
            s.tau.copy_from_slice(&row[row.len() - torques..]);
            each(s);
            return Ok(());
        }
        if self.rows.len() == 3 {
            self.rows.pop_front();
        }
        self.rows.push_back((line, row));
        if self.rows.len() == 3 {
            if self.count == 3 {
                self.emit(0, each)?;
            }
            self.emit(1, each)?;
        }
        Ok(())
    }

    /// Passes the last sample; the number of samples. `last_line` is the file's, where an
    /// error about the whole file is placed.
    ///
    /// # Errors
    /// No samples, fewer than three where derivatives must be estimated, or a derivative that
    /// is not finite.
    pub fn finish(
        &mut self,
        last_line: usize,
        each: &mut impl FnMut(&Sample),
    ) -> Result<usize, CsvError> {
        let error = |message: String| CsvError {
            line: last_line,
            column: None,
            message,
        };
        if self.count == 0 {
            return Err(error("no samples after the header".into()));
        }
        if self.given != Given::Accelerations {
            if self.count < 3 {
                return Err(error(format!(
                    "{} samples: estimating q̇ and q̈ takes at least 3 (or give the qd and qdd \
                     columns)",
                    self.count
                )));
            }
            self.emit(2, each)?;
        }
        Ok(self.count)
    }

    /// Sample `k` of the window, with the derivatives of the quadratic through the window.
    fn emit(&mut self, k: usize, each: &mut impl FnMut(&Sample)) -> Result<(), CsvError> {
        let n = self.n;
        let rows = &self.rows;
        let t = [rows[0].1[0], rows[1].1[0], rows[2].1[0]];
        let (first, second) = lagrange_derivatives(t, t[k]);
        let column = |c: usize| [rows[0].1[c], rows[1].1[c], rows[2].1[c]];
        let s = &mut self.sample;
        (s.t, s.line, s.given) = (t[k], rows[k].0, self.given);
        s.q.copy_from_slice(&rows[k].1[1..=n]);
        for j in 0..n {
            let x = column(1 + j);
            match self.given {
                Given::Positions => {
                    s.qd[j] = differentiate(first, x);
                    s.qdd[j] = differentiate(second, x);
                }
                _ => {
                    let v = column(1 + n + j);
                    s.qd[j] = v[k];
                    s.qdd[j] = differentiate(first, v);
                }
            }
        }
        if let Some(j) = (0..n).find(|&j| !(s.qd[j].is_finite() && s.qdd[j].is_finite())) {
            // The column differentiated: q, or q̇ where the file gives it.
            let (c, name) = match self.given {
                Given::Positions => (2 + j, format!("q{}", j + 1)),
                _ => (2 + n + j, format!("qd{}", j + 1)),
            };
            return Err(CsvError {
                line: rows[k].0,
                column: Some((c, name)),
                message: format!(
                    "central differences give q̇ = {}, q̈ = {} here, not finite numbers: the \
                     values change too much for steps of t of {:e} and {:e} s",
                    s.qd[j],
                    s.qdd[j],
                    t[1] - t[0],
                    t[2] - t[1]
                ),
            });
        }
        let torques = s.tau.len();
        let row = &rows[k].1;
        s.tau.copy_from_slice(&row[row.len() - torques..]);
        each(s);
        Ok(())
    }
}

/// `Σ_k w_k x_k` for weights that sum to zero, taken from the middle sample (module doc).
fn differentiate(w: [f64; 3], x: [f64; 3]) -> f64 {
    w[0] * (x[0] - x[1]) + w[2] * (x[2] - x[1])
}

/// The weights of the first and second derivative at `x` of the quadratic through
/// `(t_k, x_k)`: `L_k'(x)` and `L_k''`.
pub fn lagrange_derivatives(t: [f64; 3], x: f64) -> ([f64; 3], [f64; 3]) {
    let mut first = [0.0; 3];
    let mut second = [0.0; 3];
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let denominator = (t[k] - t[i]) * (t[k] - t[j]);
        first[k] = ((x - t[i]) + (x - t[j])) / denominator;
        second[k] = 2.0 / denominator;
    }
    (first, second)
}
