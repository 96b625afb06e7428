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
fn joint_sigmas(
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Normal deviates from a fixed seed (xorshift64 and Box-Muller).
    struct Noise(u64);

    impl Noise {
        fn uniform(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }

        fn normal(&mut self) -> f64 {
            let (u, v) = (self.uniform().max(1e-300), self.uniform());
            (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
        }
    }

    /// Two joints, parameters [a, b, c, d]: `τ1 = a x + b`, `τ2 = c y + d x² + b`, the noise
    /// of joint 2 a hundred times joint 1's. Rows as the test builds them for its own solution.
    fn rows(noise: &mut Noise) -> Vec<(usize, Vec<f64>, f64)> {
        let pi = [2.0, -1.0, 0.5, 3.0];
        let mut out = Vec::new();
        for k in 0..400 {
            let x = (f64::from(k) * 0.37).sin();
            let y = (f64::from(k) * 0.11).cos();
            let y1 = [x, 1.0, 0.0, 0.0];
            let y2 = [0.0, 1.0, y, x * x];
            let dot = |r: &[f64; 4]| r.iter().zip(pi).map(|(a, b)| a * b).sum::<f64>();
            out.push((0, y1.to_vec(), dot(&y1) + 0.01 * noise.normal()));
            out.push((1, y2.to_vec(), dot(&y2) + noise.normal()));
        }
        out
    }

    fn measured(rows: &[(usize, Vec<f64>, f64)]) -> Measured {
        let columns = vec![vec![0, 1], vec![1, 2, 3]];
        let mut m = Measured::new(columns.clone(), 4);
        for (i, row, tau) in rows {
            let own: Vec<f64> = columns[*i].iter().map(|&k| row[k]).collect();
            m.push(*i, &own, *tau);
        }
        m
    }

    /// `(Σ w² yᵀy)⁻¹` and the solution of the weighted normal equations, by Gauss-Jordan
    /// elimination: the textbook route, independent of the factors.
    fn normal_equations(rows: &[(usize, Vec<f64>, f64)], w: [f64; 2]) -> (Vec<f64>, Vec<Vec<f64>>) {
        let mut a = vec![vec![0.0; 9]; 4];
        for (i, y, tau) in rows {
            for r in 0..4 {
                for c in 0..4 {
                    a[r][c] += w[*i] * w[*i] * y[r] * y[c];
                }
                a[r][8] += w[*i] * w[*i] * y[r] * tau;
            }
        }
        for (r, row) in a.iter_mut().enumerate() {
            row[4 + r] = 1.0;
        }
        for c in 0..4 {
            let pivot = a[c][c];
            a[c].iter_mut().for_each(|x| *x /= pivot);
            for r in (0..4).filter(|&r| r != c) {
                let f = a[r][c];
                let source = a[c].clone();
                a[r].iter_mut().zip(source).for_each(|(x, s)| *x -= f * s);
            }
        }
        let solution = a.iter().map(|row| row[8]).collect();
        (solution, a.iter().map(|row| row[4..8].to_vec()).collect())
    }

    #[test]
    fn two_step_weighted_least_squares_as_the_normal_equations_give_it() {
        let rows = rows(&mut Noise(0x9e37_79b9_7f4a_7c15));
        let e = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
        // Step 1 by hand: the ordinary fit, then each joint's σ over N − c_i.
        let (ordinary, _) = normal_equations(&rows, [1.0, 1.0]);
        let sigma: Vec<f64> = [(0, 2.0), (1, 3.0)]
            .iter()
            .map(|&(i, c)| {
                let ss: f64 = rows
                    .iter()
                    .filter(|r| r.0 == i)
                    .map(|(_, y, t)| {
                        (y.iter().zip(&ordinary).map(|(a, b)| a * b).sum::<f64>() - t).powi(2)
                    })
                    .sum();
                (ss / (400.0 - c)).sqrt()
            })
            .collect();
        for (got, want) in e.sigma.iter().zip(&sigma) {
            assert!((got - want).abs() < 1e-10 * want, "{:?} {sigma:?}", e.sigma);
        }
        // Step 2: weights 1/σ_i; the covariance σ̂² (YᵀWY)⁻¹ with σ̂² over nN − b.
        let (weighted, inverse) = normal_equations(&rows, [1.0 / sigma[0], 1.0 / sigma[1]]);
        let ss: f64 = rows
            .iter()
            .map(|(i, y, t)| {
                let r = y.iter().zip(&weighted).map(|(a, b)| a * b).sum::<f64>() - t;
                (r / sigma[*i]).powi(2)
            })
            .sum();
        let variance = ss / (800.0 - 4.0);
        for k in 0..4 {
            assert!((e.values[k] - weighted[k]).abs() < 1e-10, "{k}");
            let deviation = (variance * inverse[k][k]).sqrt();
            assert!(
                (e.deviations[k] - deviation).abs() < 1e-8 * deviation,
                "{k}"
            );
            // And the truth is within a few standard deviations.
            let truth = [2.0, -1.0, 0.5, 3.0][k];
            assert!(
                (e.values[k] - truth).abs() < 4.0 * deviation,
                "{k}: {}",
                e.values[k]
            );
        }
        assert!(e.weighted && e.unidentified.is_empty() && e.samples == 400);
    }

    /// Joint 1's torques are a hundred times less noisy than joint 2's, and share parameter b
    /// with them: the ordinary fit's b carries joint 2's noise into joint 1's residual, so its
    /// σ_1 is too large; iterated, σ_1 comes from the weighted fit, and the σ_i are a fixed
    /// point: those of the final fit's own residuals, to the 1 % at which iteration stops.
    #[test]
    fn iterated_weights_come_from_the_weighted_fit() {
        let rows = rows(&mut Noise(0x9e37_79b9_7f4a_7c15));
        let once = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
        let mut m = measured(&rows);
        let e = estimate(&mut m, 1e-8, ITERATIONS).unwrap();
        assert!(
            e.reweighted > 0 && e.reweighted <= ITERATIONS,
            "{}",
            e.reweighted
        );
        let kept = [0, 1, 2, 3];
        let own = joint_sigmas(&mut m, &kept, &e.values, 400).unwrap();
        for (got, want) in e.sigma.iter().zip(&own) {
            assert!((got / want - 1.0).abs() < SETTLED, "{:?} {own:?}", e.sigma);
        }
        // Noise 0.01 put in joint 1: the iterated σ_1 nearer it than the ordinary fit's.
        let error = |s: f64| (s / 0.01 - 1.0).abs();
        assert!(
            error(e.sigma[0]) < error(once.sigma[0]),
            "{} {}",
            e.sigma[0],
            once.sigma[0]
        );
        assert!(error(e.sigma[0]) < 0.1, "{:?} {:?}", e.sigma, once.sigma);
    }

    #[test]
    fn exact_data_are_fitted_exactly() {
        let rows: Vec<_> = rows(&mut Noise(1))
            .into_iter()
            .map(|(i, y, _)| {
                let tau = y
                    .iter()
                    .zip([2.0, -1.0, 0.5, 3.0])
                    .map(|(a, b)| a * b)
                    .sum();
                (i, y, tau)
            })
            .collect();
        let e = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
        for (got, want) in e.values.iter().zip([2.0, -1.0, 0.5, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{:?}", e.values);
        }
        assert!(e.rms.iter().all(|&r| r < 1e-12), "{:?}", e.rms);
        assert!(e.condition > 1.0 && e.condition.is_finite());
    }
}
