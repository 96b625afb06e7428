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
//! On a floating base (Pinocchio's free flyer) the base's velocity `v` is its twist in its own
//! frame, not the derivative of `q`'s entries: each neighbour's configuration is taken as the
//! tangent from the sample's own, `δ_k = difference(q, q_k)` (the runtime's, the logarithm of
//! `M⁻¹ M_k` for the base, `q_k,i − q_i` for a joint), and `v = Σ_k L_k' δ_k`, `a = Σ_k L_k''
//! δ_k`: along `q(t) = q ⊕ ξ(t)`, `ξ̇ = J_r(ξ)⁻¹ v` and `J_r(0) = 1`, `J̇_r(0) ξ̇ = −½ [ξ̇, ξ̇] =
//! 0`, so `ξ̇ = v` and `ξ̈ = v̇` at the sample: second order in the steps as a joint's. The
//! base's quaternion must be of unit norm (within [`QUATERNION_NORM`]), and is normalised.
//!
//! A derivative that is not finite (time steps so short, or values so large, that the
//! differences overflow) is an error at the sample's line, in the column it was taken of.

use super::csv::{Base, Columns, CsvError, Given};
use super::Sample;
use std::collections::VecDeque;

/// A floating base's quaternion may differ from unit norm by this much (a file's rounding):
/// more is an error, not normalised, as a wrong column or order (`w` first) would be.
pub const QUATERNION_NORM: f64 = 1e-6;

/// The last three rows and their lines, for derivatives by the quadratic through them.
pub struct Differences {
    columns: Columns,
    rows: VecDeque<(usize, Vec<f64>)>,
    given: Given,
    count: usize,
    sample: Sample,
    /// A floating base's tangents to the window's rows.
    tangents: [Vec<f64>; 3],
}

impl Differences {
    /// For the files of these columns.
    pub fn new(columns: Columns) -> Differences {
        let (nq, nv) = (columns.positions(), columns.rates());
        Differences {
            columns,
            rows: VecDeque::with_capacity(3),
            given: Given::Positions,
            count: 0,
            sample: Sample {
                t: 0.0,
                q: vec![0.0; nq],
                qd: vec![0.0; nv],
                qdd: vec![0.0; nv],
                tau: Vec::new(),
                line: 0,
                given: Given::Positions,
            },
            tangents: std::array::from_fn(|_| vec![0.0; nv]),
        }
    }

    /// How q̇ and q̈ were had.
    pub fn method(&self) -> &'static str {
        match (self.given, self.columns.base) {
            (Given::Positions, Base::Fixed) => "q̇ and q̈ by central differences",
            (Given::Velocities, Base::Fixed) => "q̈ by central differences of q̇",
            (Given::Accelerations, Base::Fixed) => "q̇ and q̈ given",
            (Given::Positions, _) => "v and a by central differences along the configuration space",
            (Given::Velocities, _) => "a by central differences of v",
            (Given::Accelerations, _) => "v and a given",
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
        mut row: Vec<f64>,
        each: &mut impl FnMut(&Sample),
    ) -> Result<(), CsvError> {
        self.given = given;
        self.count += 1;
        let (nq, nv) = (self.columns.positions(), self.columns.rates());
        // The file's torques, after the given groups.
        let torques = row.len() - 1 - nq - (given.groups() - 1) * nv;
        self.sample.tau.resize(torques, 0.0);
        if matches!(self.columns.base, Base::Floating { .. }) {
            unit_quaternion(line, &mut row[4..8])?;
        }
        if self.given == Given::Accelerations {
            let s = &mut self.sample;
            (s.t, s.line, s.given) = (row[0], line, given);
            s.q.copy_from_slice(&row[1..=nq]);
            s.qd.copy_from_slice(&row[nq + 1..=nq + nv]);
            s.qdd.copy_from_slice(&row[nq + nv + 1..=nq + 2 * nv]);
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
        let (nq, nv) = (self.columns.positions(), self.columns.rates());
        let rows = &self.rows;
        let t = [rows[0].1[0], rows[1].1[0], rows[2].1[0]];
        let (first, second) = lagrange_derivatives(t, t[k]);
        let column = |c: usize| [rows[0].1[c], rows[1].1[c], rows[2].1[c]];
        let floating = matches!(self.columns.base, Base::Floating { .. });
        if floating && self.given == Given::Positions {
            for (m, tangent) in self.tangents.iter_mut().enumerate() {
                configuration_difference(&rows[k].1[1..=nq], &rows[m].1[1..=nq], tangent);
            }
        }
        let s = &mut self.sample;
        (s.t, s.line, s.given) = (t[k], rows[k].0, self.given);
        s.q.copy_from_slice(&rows[k].1[1..=nq]);
        for j in 0..nv {
            match self.given {
                Given::Positions if floating => {
                    let x = self.tangents.each_ref().map(|d| d[j]);
                    s.qd[j] = first.iter().zip(x).map(|(w, x)| w * x).sum();
                    s.qdd[j] = second.iter().zip(x).map(|(w, x)| w * x).sum();
                }
                Given::Positions => {
                    let x = column(1 + j);
                    s.qd[j] = differentiate(first, x);
                    s.qdd[j] = differentiate(second, x);
                }
                _ => {
                    let v = column(1 + nq + j);
                    s.qd[j] = v[k];
                    s.qdd[j] = differentiate(first, v);
                }
            }
        }
        if let Some(j) = (0..nv).find(|&j| !(s.qd[j].is_finite() && s.qdd[j].is_finite())) {
            // The column differentiated: q (a floating base's first, or its joint's), or q̇.
            let [qd, _] = self.columns.derivative_names();
            let (c, name) = match self.given {
                Given::Positions if floating => {
                    let c = if j < 6 { 0 } else { j + 1 };
                    (2 + c, format!("q{}", c + 1))
                }
                Given::Positions => (2 + j, format!("q{}", j + 1)),
                _ => (2 + nq + j, format!("{qd}{}", j + 1)),
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

/// The quaternion `x, y, z, w` of a floating base's row at `line` (its columns 5 to 8)
/// normalised; an error if its norm is not 1 within [`QUATERNION_NORM`].
pub fn unit_quaternion(line: usize, quaternion: &mut [f64]) -> Result<(), CsvError> {
    let norm = quaternion.iter().map(|x| x * x).sum::<f64>().sqrt();
    if (norm - 1.0).abs() <= QUATERNION_NORM {
        quaternion.iter_mut().for_each(|x| *x /= norm);
        return Ok(());
    }
    Err(CsvError {
        line,
        column: Some((5, "q4".into())),
        message: format!(
            "the base's orientation q4..q7 (qx, qy, qz, qw: Pinocchio's order, w last) has \
             norm {norm:e}, not 1 (within {QUATERNION_NORM:e}): a rotation is a unit quaternion"
        ),
    })
}

/// The tangent from `q0` to `q1` of a floating base's configurations (`x, y, z, qx, qy, qz,
/// qw`, then the joints): the runtime's `difference`, the base's twist `log6(M0⁻¹ M1)` in its
/// frame at `q0`, then `q1_i − q0_i`.
fn configuration_difference(q0: &[f64], q1: &[f64], out: &mut [f64]) {
    let base = |q: &[f64]| -> [f64; 7] { std::array::from_fn(|i| q[i]) };
    let twist: [f64; 6] = dynamics_runtime::configuration::difference(&base(q0), &base(q1));
    out[..6].copy_from_slice(&twist);
    for i in 6..out.len() {
        out[i] = q1[i + 1] - q0[i + 1];
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
