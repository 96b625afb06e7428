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

use super::csv::Given;
use super::Sample;
use std::collections::VecDeque;

/// The last three rows, for derivatives by the quadratic through them.
pub struct Differences {
    n: usize,
    rows: VecDeque<Vec<f64>>,
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

    /// Takes the next row (`t`, the columns `given`, the torques if any), passing to `each`
    /// every sample whose derivatives are now known.
    pub fn push(&mut self, given: Given, row: Vec<f64>, each: &mut impl FnMut(&Sample)) {
        self.given = given;
        self.count += 1;
        if self.given == Given::Accelerations {
            let n = self.n;
            let s = &mut self.sample;
            s.t = row[0];
            s.q.copy_from_slice(&row[1..=n]);
            s.qd.copy_from_slice(&row[n + 1..=2 * n]);
            s.qdd.copy_from_slice(&row[2 * n + 1..=3 * n]);
            let torques = s.tau.len();
            s.tau.copy_from_slice(&row[row.len() - torques..]);
            each(s);
            return;
        }
        if self.rows.len() == 3 {
            self.rows.pop_front();
        }
        self.rows.push_back(row);
        if self.rows.len() == 3 {
            if self.count == 3 {
                self.emit(0, each);
            }
            self.emit(1, each);
        }
    }

    /// Passes the last sample; the number of samples.
    ///
    /// # Errors
    /// No samples, or fewer than three where derivatives must be estimated.
    pub fn finish(&mut self, each: &mut impl FnMut(&Sample)) -> Result<usize, String> {
        if self.count == 0 {
            return Err("no samples after the header".into());
        }
        if self.given != Given::Accelerations {
            if self.count < 3 {
                return Err(format!(
                    "{} samples: estimating q̇ and q̈ takes at least 3 (or give the qd and qdd \
                     columns)",
                    self.count
                ));
            }
            self.emit(2, each);
        }
        Ok(self.count)
    }

    /// Sample `k` of the window, with the derivatives of the quadratic through the window.
    fn emit(&mut self, k: usize, each: &mut impl FnMut(&Sample)) {
        let n = self.n;
        let rows = &self.rows;
        let t = [rows[0][0], rows[1][0], rows[2][0]];
        let (first, second) = lagrange_derivatives(t, t[k]);
        let column = |c: usize| [rows[0][c], rows[1][c], rows[2][c]];
        let s = &mut self.sample;
        s.t = t[k];
        s.q.copy_from_slice(&rows[k][1..=n]);
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
        let torques = s.tau.len();
        let row = &rows[k];
        s.tau.copy_from_slice(&row[row.len() - torques..]);
        each(s);
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
