//! The weighted least-squares estimate of Gautier and Poignet (2001), from the joints'
//! factors ([`Measured`]), for N samples of n joints:
//!
//! 1. **Identifiable parameters** ([`rank`]): those whose columns of the stacked `Y` are
//!    independent of the columns before them, to the tolerance; the others are named, not
//!    estimated.
//! 2. **Ordinary least squares** `π̂ = argmin ‖Y π − τ‖²`, then per joint the residual variance
//!    `σ_i² = ‖Y_i π̂ − τ_i‖² / (N − c_i)`, with `c_i` the identified parameters in joint i's
//!    equation.
//! 3. **Weighted least squares** with the rows of joint i scaled by `1/σ_i`:
//!    `π̂_w = argmin Σ_i ‖Y_i π − τ_i‖² / σ_i²`, by the factor `R_w` of the weighted stack
//!    (`R_w π̂_w = z_w`, back substitution).
//! 4. **Standard deviations** `σ_π̂k² = σ̂² [(Y_wᵀ Y_w)⁻¹]_kk = σ̂² Σ_j [R_w⁻¹]_kj²`, with
//!    `σ̂² = ρ_w² / (nN − b)` the weighted residual's variance (close to 1 when the weights are
//!    right), b the number of identified parameters; relative standard deviation
//!    `100 σ_π̂k / |π̂_k|` %.
//! 5. **Condition number** of the weighted stacked regressor, `σ_max(R_w) / σ_min(R_w)`
//!    ([`singular_values`]): `Y_w` and `R_w` have the same singular values.
//!
//! **Iterated weights** (`--iterate-weights`): step 3's σ_i come from the ordinary fit, in which a
//! joint of small torques shares parameters with joints of large noise, whose residuals then
//! inflate its σ_i (and shrink its weight). Iterated, σ_i are re-estimated from the weighted
//! fit's residuals, `σ_i² = ‖Y_i π̂_w − τ_i‖² / (N − c_i)`, and the weighted fit repeated, until
//! no σ_i changes by more than 1 %, at most [`ITERATIONS`] times; steps 4 and 5 use the last
//! weights.
//!
//! A joint fitted exactly (noise-free data) has `σ_i = 0`: each σ_i is taken no smaller than
//! 10⁻⁶ of the largest, so that a joint's round-off is not weighted as information; when every
//! σ_i is zero the weights are all one.

use super::measured::Measured;
use super::rank::{self, Unidentified};
use crate::linear_algebra::{back_substitute, inverse, singular_values};

/// The smallest σ_i relative to the largest, where weights are capped.
const WEIGHT_RANGE: f64 = 1e-6;

/// Re-estimated weights have settled when no σ_i changes by this fraction.
pub const SETTLED: f64 = 0.01;

/// The most times `--iterate-weights` re-estimates them.
pub const ITERATIONS: usize = 10;

/// The estimate.
#[derive(Clone, Debug)]
pub struct Estimate {
    /// Per parameter: its estimate and standard deviation (NaN for one not identified).
    pub values: Vec<f64>,
    pub deviations: Vec<f64>,
    pub unidentified: Vec<Unidentified>,
    /// Per joint: σ_i of the ordinary fit (of the last weighted fit when the weights were
    /// iterated), whose inverse weighted its rows (zero when weights
    /// were not applied).
    pub sigma: Vec<f64>,
    /// Whether the rows were weighted (every σ_i zero: not).
    pub weighted: bool,
    /// Per joint: the weight its rows had in the fit (1 when not weighted).
    pub weights: Vec<f64>,
    /// How many times the weights were re-estimated from a weighted fit (0: from the ordinary
    /// fit only).
    pub reweighted: usize,
    /// Per joint: the residual's root mean square with the weighted estimate.
    pub rms: Vec<f64>,
    /// Of the weighted stacked regressor of the identified parameters.
    pub condition: f64,
    pub samples: usize,
}

/// The estimate from `measured`, with `tolerance` for the rank ([`rank::identifiable`]), the
/// weights re-estimated up to `iterations` times: σ_i from the residuals of the last weighted
/// fit instead of the ordinary one's, until no σ_i changes by more than [`SETTLED`] (0:
/// Gautier's two steps).
///
/// # Errors
/// Fewer samples than a joint's identified parameters, or no identifiable parameter.
pub fn estimate(
    measured: &mut Measured,
    tolerance: f64,
    iterations: usize,
) -> Result<Estimate, String> {
    let (n, p, samples) = (
        measured.joints.len(),
        measured.parameters,
        measured.samples(),
    );
    let all: Vec<usize> = (0..p).collect();
    let (r0, _, _) = measured.stacked(&all, &vec![1.0; n]);
    let (kept, unidentified) = rank::identifiable(&r0, p, tolerance);
    if kept.is_empty() {
        return Err("the data identify none of the parameters".into());
    }
    let ordinary = solve(measured, &kept, &vec![1.0; n]);
    let mut sigma = joint_sigmas(measured, &kept, &ordinary, samples)?;
    let mut reweighted = 0;
    while reweighted < iterations && sigma.iter().any(|&s| s > 0.0) {
        let fit = solve(measured, &kept, &weights_of(&sigma).0);
        let next = joint_sigmas(measured, &kept, &fit, samples)?;
        let change = sigma
            .iter()
            .zip(&next)
            .map(|(a, b)| if *a > 0.0 { (b / a - 1.0).abs() } else { 0.0 })
            .fold(0.0, f64::max);
        sigma = next;
        reweighted += 1;
        if change < SETTLED {
            break;
        }
    }
    let (weights, weighted) = weights_of(&sigma);
    let (r, z, rho) = measured.stacked(&kept, &weights);
    let b = kept.len();
    let solution = back_substitute(&r, b, &z);
    let dof = (n * samples).saturating_sub(b).max(1);
    let variance = rho * rho / dof as f64;
    let inv = inverse(&r, b);
    let mut values = vec![f64::NAN; p];
    let mut deviations = vec![f64::NAN; p];
    for (i, &k) in kept.iter().enumerate() {
        values[k] = solution[i];
        let norm: f64 = inv[i * b..(i + 1) * b].iter().map(|x| x * x).sum();
        deviations[k] = (variance * norm).sqrt();
    }
    let full: Vec<f64> = values
        .iter()
        .map(|v| if v.is_nan() { 0.0 } else { *v })
        .collect();
    let rms = measured
        .joints
        .iter_mut()
        .map(|j| (j.squared_residual(&full) / samples as f64).sqrt())
        .collect();
    let singular = singular_values(&r, b);
    Ok(Estimate {
        values,
        deviations,
        unidentified,
        sigma: if weighted { sigma } else { vec![0.0; n] },
        weighted,
        weights,
        reweighted,
        rms,
        condition: singular[0] / singular[b - 1],
        samples,
    })
}

/// The weights `1/σ_i` (σ_i no smaller than 10⁻⁶ of the largest), and whether they are weights:
/// all ones when every σ_i is zero.
fn weights_of(sigma: &[f64]) -> (Vec<f64>, bool) {
    let largest = sigma.iter().copied().fold(0.0, f64::max);
    let weighted = largest > 0.0;
    let weights = sigma
        .iter()
        .map(|&s| {
            if weighted {
                1.0 / s.max(WEIGHT_RANGE * largest)
            } else {
                1.0
            }
        })
        .collect();
    (weights, weighted)
}

/// The least-squares solution over the parameters `kept`, rows weighted by `weights`, as a
/// vector over all parameters (zero where left out).
fn solve(measured: &mut Measured, kept: &[usize], weights: &[f64]) -> Vec<f64> {
    let (r, z, _) = measured.stacked(kept, weights);
    let x = back_substitute(&r, kept.len(), &z);
    let mut full = vec![0.0; measured.parameters];
    for (&k, v) in kept.iter().zip(x) {
        full[k] = v;
    }
    full
}

/// `σ_i` of each joint for the estimate `pi`.
///
/// # Errors
/// A joint's equation with no more samples than its identified parameters.
#[doc(hidden)] // For the test that iterated weights are a fixed point.
pub fn joint_sigmas(
    measured: &mut Measured,
    kept: &[usize],
    pi: &[f64],
    samples: usize,
) -> Result<Vec<f64>, String> {
    measured
        .joints
        .iter_mut()
        .enumerate()
        .map(|(i, joint)| {
            let c = joint.columns.iter().filter(|k| kept.contains(k)).count();
            if samples <= c {
                return Err(format!(
                    "{samples} samples cannot determine the {c} parameters of joint {}'s \
                     equation",
                    i + 1
                ));
            }
            Ok((joint.squared_residual(pi) / (samples - c) as f64).sqrt())
        })
        .collect()
}
