//! The measured equations `τ_i(t) = Y_i(t) π`, one per joint and sample, held as one triangular
//! factor per joint: `[Y_i | τ_i] = Q_i R_i` over the parameters whose column is not identically
//! zero in joint i's equation (in a serial chain, joint i's torque involves no link before i:
//! the factors are smaller than the whole regressor's, and cheaper to update).
//!
//! A factor gives, for any `π`, joint i's squared residual
//! `‖Y_i π − τ_i‖² = ‖R_i [π; −1]‖²` (Q_i is orthogonal), and the factors of rows from several
//! joints, each scaled by a weight, stack into the factor of the weighted problem: everything
//! least squares needs, after a single pass over the samples.

use super::householder::Triangle;

/// Rows taken per update of a factor.
const BLOCK: usize = 64;

/// Joint i's equations.
#[derive(Clone, Debug)]
pub struct JointEquations {
    /// The parameters in joint i's equation, in the order of its factor's columns.
    pub columns: Vec<usize>,
    triangle: Triangle,
}

impl JointEquations {
    /// `‖Y_i π − τ_i‖²` for the parameters `pi` (all of the model's, zero where left out).
    pub fn squared_residual(&mut self, pi: &[f64]) -> f64 {
        let c = self.columns.len();
        let mut x: Vec<f64> = self.columns.iter().map(|&k| pi[k]).collect();
        x.push(-1.0);
        let r = self.triangle.factor();
        (0..=c)
            .map(|i| {
                (i..=c)
                    .map(|k| r[i * (c + 1) + k] * x[k])
                    .sum::<f64>()
                    .powi(2)
            })
            .sum()
    }
}

/// The equations of every joint.
#[derive(Clone, Debug)]
pub struct Measured {
    pub joints: Vec<JointEquations>,
    /// The model's parameters.
    pub parameters: usize,
    row: Vec<f64>,
}

impl Measured {
    /// No samples yet, for a model of `parameters` parameters whose joint i's equation has the
    /// parameters `columns[i]`.
    #[must_use]
    pub fn new(columns: Vec<Vec<usize>>, parameters: usize) -> Measured {
        let widest = columns.iter().map(Vec::len).max().unwrap_or(0);
        Measured {
            joints: columns
                .into_iter()
                .map(|columns| JointEquations {
                    triangle: Triangle::new(columns.len() + 1, BLOCK),
                    columns,
                })
                .collect(),
            parameters,
            row: Vec::with_capacity(widest + 1),
        }
    }

    /// Joint `i`'s equation at one sample: its regressor row (the values of its columns, in
    /// their order) and its torque.
    pub fn push(&mut self, i: usize, regressor: &[f64], tau: f64) {
        self.row.clear();
        self.row.extend_from_slice(regressor);
        self.row.push(tau);
        self.joints[i].triangle.push(&self.row);
    }

    /// The samples taken (joint 1's rows; every joint has one per sample).
    #[must_use]
    pub fn samples(&self) -> usize {
        self.joints.first().map_or(0, |j| j.triangle.rows())
    }

    /// The factor of the stacked problem restricted to the parameters `kept` (in that order),
    /// joint i's rows scaled by `weights[i]`: `(R, z, ρ)` with `R` `b × b` row-major, so that
    /// `Σ_i w_i² ‖Y_i π − τ_i‖² = ‖R π_kept − z‖² + ρ²`.
    pub fn stacked(&mut self, kept: &[usize], weights: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
        let b = kept.len();
        let mut position = vec![None; self.parameters];
        for (p, &k) in kept.iter().enumerate() {
            position[k] = Some(p);
        }
        let rows: usize = self.joints.iter().map(|j| j.columns.len() + 1).sum();
        let mut stack = Triangle::new(b + 1, rows);
        let mut row = vec![0.0; b + 1];
        for (joint, &w) in self.joints.iter_mut().zip(weights) {
            let c = joint.columns.len();
            let columns = joint.columns.clone();
            let r = joint.triangle.factor();
            for i in 0..=c {
                row.fill(0.0);
                for (l, &k) in columns.iter().enumerate() {
                    if let Some(p) = position[k] {
                        row[p] = w * r[i * (c + 1) + l];
                    }
                }
                row[b] = w * r[i * (c + 1) + c];
                stack.push(&row);
            }
        }
        let full = stack.factor();
        let r: Vec<f64> = (0..b)
            .flat_map(|i| full[i * (b + 1)..i * (b + 1) + b].to_vec())
            .collect();
        let z: Vec<f64> = (0..b).map(|i| full[i * (b + 1) + b]).collect();
        (r, z, full[b * (b + 1) + b].abs())
    }
}
