//! Which parameters the data can identify: a rank-revealing QR of the stacked regressor's
//! factor `R`, its columns taken in order (Gautier, 1990, as for numerical base parameters).
//!
//! Each column is first scaled to unit norm (`‖Y_k‖ = ‖R_k‖`), since the parameters have
//! different units. Column k is then reflected against the columns kept before it; the norm of
//! what is left below the kept rows is the sine of its angle to their span. Below `tolerance`,
//! the column is, to that accuracy, the combination `Y_k ≈ Σ_j c_j Y_j` of the kept columns, and
//! its parameter cannot be told apart from theirs: it is not estimated (its estimate's noise
//! would be amplified about `1 / tolerance` times), and each kept parameter's estimate stands
//! for `π_j + c_j π_k`. A column with no signal at all (a norm
//! below 10⁻¹² of the largest: a joint that never moves, an effect the motion never excites) is
//! left out first. Columns are taken in the model's order, so that of a dependent group the
//! later ones are named.
//!
//! By hand: nalgebra's rank-revealing QR (`ColPivQR`) chooses its columns by their norms, not
//! in the model's order, and has no tolerance to leave a column out.

use crate::linear_algebra::back_substitute;

/// A parameter the data cannot identify.
#[derive(Clone, Debug, PartialEq)]
pub struct Unidentified {
    pub parameter: usize,
    /// `(j, c_j)`: its column is `Σ c_j Y_j` of identified parameters' columns (empty when the
    /// column is zero), largest contributions first.
    pub combination: Vec<(usize, f64)>,
}

/// Columns whose norm is below this fraction of the largest have no signal.
const NO_SIGNAL: f64 = 1e-12;

/// The parameters that the `p × p` factor `r` (row-major) identifies, in order, and those it
/// does not.
#[must_use]
pub fn identifiable(r: &[f64], p: usize, tolerance: f64) -> (Vec<usize>, Vec<Unidentified>) {
    let norms: Vec<f64> = (0..p)
        .map(|k| (0..=k).map(|i| r[i * p + k].powi(2)).sum::<f64>().sqrt())
        .collect();
    let largest = norms.iter().copied().fold(0.0, f64::max);
    // Column-major, each column scaled to unit norm.
    let mut a: Vec<Vec<f64>> = (0..p)
        .map(|k| (0..p).map(|i| r[i * p + k] / norms[k]).collect())
        .collect();
    let (mut kept, mut dropped) = (Vec::new(), Vec::new());
    for k in 0..p {
        if norms[k] <= NO_SIGNAL * largest {
            dropped.push(Unidentified {
                parameter: k,
                combination: Vec::new(),
            });
            continue;
        }
        let row = kept.len();
        let rest: f64 = a[k][row..].iter().map(|x| x * x).sum::<f64>().sqrt();
        if rest <= tolerance {
            let combination = combination(&a, &kept, k, &norms);
            dropped.push(Unidentified {
                parameter: k,
                combination,
            });
            continue;
        }
        reflect(&mut a, row, k, rest);
        kept.push(k);
    }
    (kept, dropped)
}

/// Reflects rows `row..` so that column `k` is zero below `row`, and the columns after it the
/// same way.
fn reflect(a: &mut [Vec<f64>], row: usize, k: usize, norm: f64) {
    let x0 = a[k][row];
    let alpha = if x0 >= 0.0 { -norm } else { norm };
    let mut v: Vec<f64> = a[k][row..].to_vec();
    v[0] -= alpha;
    let vtv: f64 = v.iter().map(|x| x * x).sum();
    if vtv == 0.0 {
        return;
    }
    for column in a.iter_mut().skip(k) {
        let s: f64 = column[row..].iter().zip(&v).map(|(c, x)| c * x).sum();
        let f = 2.0 * s / vtv;
        for (c, x) in column[row..].iter_mut().zip(&v) {
            *c -= f * x;
        }
    }
}

/// The coefficients of dropped column `k` on the kept columns, unscaled, largest
/// contribution first.
fn combination(a: &[Vec<f64>], kept: &[usize], k: usize, norms: &[f64]) -> Vec<(usize, f64)> {
    let m = kept.len();
    // The kept columns' triangle (rows 0..m) and column k's entries in those rows.
    let triangle: Vec<f64> = (0..m)
        .flat_map(|i| kept.iter().map(move |&j| a[j][i]))
        .collect();
    let scaled = back_substitute(&triangle, m, &a[k][..m]);
    let mut terms: Vec<(usize, f64, f64)> = kept
        .iter()
        .zip(scaled)
        .filter(|(_, c)| c.abs() > 1e-9)
        .map(|(&j, c)| (j, c * norms[k] / norms[j], c.abs()))
        .collect();
    terms.sort_by(|x, y| y.2.total_cmp(&x.2));
    terms.into_iter().map(|(j, c, _)| (j, c)).collect()
}
