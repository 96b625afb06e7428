//! Singular values of a small square matrix by one-sided Jacobi rotations (Hestenes): plane
//! rotations of pairs of columns, each making its pair orthogonal, are repeated until every pair
//! is orthogonal to working precision; the columns' norms are then the singular values. For an
//! `R` with `AᵀA = RᵀR` they are those of `A`, so `cond(A) = σ_max / σ_min` comes from `R`
//! alone. Slower than bidiagonalisation for large matrices, but accurate even for the small
//! singular values (Demmel and Veselić, 1992), and short.

/// The singular values of the `n × n` matrix `a` (row-major), largest first.
#[must_use]
pub fn singular_values(a: &[f64], n: usize) -> Vec<f64> {
    // Column-major copy: the rotations act on columns.
    let mut cols: Vec<Vec<f64>> = (0..n)
        .map(|j| (0..n).map(|i| a[i * n + j]).collect())
        .collect();
    for _sweep in 0..60 {
        let mut rotated = false;
        for p in 0..n {
            for q in p + 1..n {
                rotated |= orthogonalise(&mut cols, p, q);
            }
        }
        if !rotated {
            break;
        }
    }
    let mut values: Vec<f64> = cols
        .iter()
        .map(|c| c.iter().map(|x| x * x).sum::<f64>().sqrt())
        .collect();
    values.sort_by(|x, y| y.total_cmp(x));
    values
}

/// Rotates columns `p` and `q` to be orthogonal; whether they were not already.
fn orthogonalise(cols: &mut [Vec<f64>], p: usize, q: usize) -> bool {
    let (left, right) = cols.split_at_mut(q);
    let (x, y) = (&mut left[p], &mut right[0]);
    let alpha: f64 = x.iter().map(|v| v * v).sum();
    let beta: f64 = y.iter().map(|v| v * v).sum();
    let gamma: f64 = x.iter().zip(y.iter()).map(|(a, b)| a * b).sum();
    if gamma == 0.0 || gamma.abs() <= f64::EPSILON * (alpha * beta).sqrt() {
        return false;
    }
    // The rotation that zeroes the pair's off-diagonal entry of the Gram matrix.
    let zeta = (beta - alpha) / (2.0 * gamma);
    let t = zeta.signum() / (zeta.abs() + zeta.hypot(1.0));
    let c = 1.0 / t.hypot(1.0);
    let s = c * t;
    for (a, b) in x.iter_mut().zip(y.iter_mut()) {
        let (u, v) = (*a, *b);
        *a = c * u - s * v;
        *b = s * u + c * v;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `U diag(σ) Vᵀ` with U and V plane rotations: its singular values are σ.
    #[test]
    fn the_singular_values_of_a_rotated_diagonal() {
        let sigma = [1e3, 2.0, 0.5, 1e-4];
        let n = 4;
        let rotation = |angle: f64, i: usize, j: usize| {
            let mut m = vec![0.0; n * n];
            for k in 0..n {
                m[k * n + k] = 1.0;
            }
            let (s, c) = angle.sin_cos();
            m[i * n + i] = c;
            m[j * n + j] = c;
            m[i * n + j] = -s;
            m[j * n + i] = s;
            m
        };
        let product = |a: &[f64], b: &[f64]| -> Vec<f64> {
            let mut m = vec![0.0; n * n];
            for i in 0..n {
                for j in 0..n {
                    m[i * n + j] = (0..n).map(|k| a[i * n + k] * b[k * n + j]).sum();
                }
            }
            m
        };
        let mut d = vec![0.0; n * n];
        for k in 0..n {
            d[k * n + k] = sigma[k];
        }
        let u = product(&rotation(0.3, 0, 2), &rotation(-1.1, 1, 3));
        let v = product(&rotation(0.7, 0, 1), &rotation(2.0, 2, 3));
        let a = product(&product(&u, &d), &v);
        let values = singular_values(&a, n);
        for (got, want) in values.iter().zip(sigma) {
            assert!((got - want).abs() <= 1e-12 * want.max(1.0), "{values:?}");
        }
    }

    #[test]
    fn a_singular_matrix_has_a_zero_singular_value() {
        let values = singular_values(&[1.0, 2.0, 2.0, 4.0], 2);
        assert!(
            (values[0] - 5.0).abs() < 1e-14 && values[1].abs() < 1e-15,
            "{values:?}"
        );
    }
}
