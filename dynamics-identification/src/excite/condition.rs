//! The condition number of the stacked base regressor over the samples of a motion,
//! `cond(Y_B) = σ_max / σ_min` with `Y_B` the rows `Y_B(q(t_k), q̇(t_k), q̈(t_k))` of every
//! sample k and joint stacked (`n N × b`). It bounds how much the relative error of the torques
//! can grow in the least-squares estimate of the base parameters: the lower, the better the
//! motion excites them (Gautier and Khalil, 1992; Swevers et al., 1997).
//!
//! * [`Gram`], for the search: `G = Y_Bᵀ Y_B = Σ_i Σ_k y_ikᵀ y_ik` accumulated over the samples
//!   (joint i's row only over the parameters in its equation), then
//!   `cond = √(λ_max(G) / λ_min(G))` ([`symmetric_eigenvalues`]): cheap, and accurate to a
//!   relative `ε cond²`, which is plenty to rank candidates.
//! * [`Factor`], for the report: the factor `R` of the stacked `Y_B` by Householder
//!   reflections and its singular values (nalgebra's SVD), as `dynamics identify`
//!   computes its condition number (with every joint's weight 1).

use crate::identify::measured::Measured;
use crate::identify::model::{JointValues, LinearModel, Work};
use crate::lanes::LANES;
use crate::linear_algebra::{singular_values, symmetric_eigenvalues};

/// The Gram matrix of the stacked regressor, accumulated sample by sample: per joint over the
/// parameters of its equation (a dense lower triangle, whose update is a contiguous loop), the
/// joints' summed into `YᵀY` when the condition number is asked for.
pub struct Gram<'m> {
    model: &'m LinearModel,
    work: Work,
    entries: Vec<f64>,
    /// Per joint i, `Σ_k y_ikᵀ y_ik` over its columns: lower triangle, row-major, `c_i × c_i`.
    joints: Vec<Vec<f64>>,
}

impl<'m> Gram<'m> {
    #[must_use]
    pub fn new(model: &'m LinearModel) -> Gram<'m> {
        Gram {
            model,
            work: Work::default(),
            entries: vec![0.0; LANES * model.entries()],
            joints: model
                .columns
                .iter()
                .map(|c| vec![0.0; c.len() * c.len()])
                .collect(),
        }
    }

    /// Starts again with no samples.
    pub fn clear(&mut self) {
        for joint in &mut self.joints {
            joint.fill(0.0);
        }
    }

    /// Adds the rows of the samples, [`LANES`] at a time.
    pub fn push(&mut self, states: &[JointValues<'_>]) {
        let entries = self.model.entries();
        for group in states.chunks(LANES) {
            self.model.rows(group, &mut self.work, &mut self.entries);
            for k in 0..group.len() {
                let sample = &self.entries[k * entries..(k + 1) * entries];
                add(&mut self.joints, &self.model.columns, sample);
            }
        }
    }

    /// `√(λ_max / λ_min)` of the samples pushed; infinite where the regressor is rank
    /// deficient.
    pub fn condition(&self) -> f64 {
        let b = self.model.names.len();
        let mut gram = vec![0.0; b * b];
        // The columns are in increasing order: (x, y ≤ x) lands in the lower triangle.
        for (joint, columns) in self.joints.iter().zip(&self.model.columns) {
            let c = columns.len();
            for (x, &cx) in columns.iter().enumerate() {
                for (y, &cy) in columns[..=x].iter().enumerate() {
                    gram[cx * b + cy] += joint[x * c + y];
                }
            }
        }
        let eigen = symmetric_eigenvalues(&gram, b);
        let (smallest, largest) = (eigen[0], eigen[b - 1]);
        if smallest > 0.0 {
            (largest / smallest).sqrt()
        } else {
            f64::INFINITY
        }
    }
}

/// Adds one sample's entries to each joint's lower triangle.
fn add(joints: &mut [Vec<f64>], columns: &[Vec<usize>], entries: &[f64]) {
    let mut start = 0;
    for (joint, columns) in joints.iter_mut().zip(columns) {
        let c = columns.len();
        let row = &entries[start..start + c];
        for (x, &rx) in row.iter().enumerate() {
            let lower = &mut joint[x * c..=x * c + x];
            for (g, &ry) in lower.iter_mut().zip(row) {
                *g += rx * ry;
            }
        }
        start += c;
    }
}

/// The Householder factor of the stacked regressor, fed samples in chunks (so that a period of
/// many samples is never held); its `σ_max / σ_min`.
pub struct Factor<'m> {
    model: &'m LinearModel,
    measured: Measured,
    work: Work,
    rows: Vec<f64>,
}

impl<'m> Factor<'m> {
    #[must_use]
    pub fn new(model: &'m LinearModel) -> Factor<'m> {
        Factor {
            model,
            measured: Measured::new(model.columns.clone(), model.names.len()),
            work: Work::default(),
            rows: vec![0.0; LANES * model.entries()],
        }
    }

    /// Adds the rows of the samples `states`.
    pub fn push(&mut self, states: &[JointValues<'_>]) {
        let (model, entries) = (self.model, self.model.entries());
        for group in states.chunks(LANES) {
            model.rows(group, &mut self.work, &mut self.rows);
            for k in 0..group.len() {
                let sample = &self.rows[k * entries..(k + 1) * entries];
                let mut start = 0;
                for (i, columns) in model.columns.iter().enumerate() {
                    self.measured
                        .push(i, &sample[start..start + columns.len()], 0.0);
                    start += columns.len();
                }
            }
        }
    }

    /// `σ_max / σ_min` of the samples pushed.
    pub fn condition(mut self) -> f64 {
        let b = self.model.names.len();
        let all: Vec<usize> = (0..b).collect();
        let (r, _, _) = self.measured.stacked(&all, &vec![1.0; self.model.joints()]);
        let singular = singular_values(&r, b);
        singular[0] / singular[b - 1]
    }
}
