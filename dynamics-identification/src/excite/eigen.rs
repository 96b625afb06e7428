//! The eigenvalues of a symmetric matrix, for the condition number `√(λ_max / λ_min)` of a
//! Gram matrix `YᵀY`, thousands of times in a search: `n³` operations, where the one-sided
//! Jacobi rotations of `identify::singular` take several times that.
//!
//! 1. **Householder tridiagonalisation** (Golub and Van Loan, *Matrix Computations*, 4th ed.,
//!    algorithm 8.3.1): for k = 0..n−2, the reflection `P = I − β v vᵀ` that maps
//!    `x = A[k+1.., k]` onto `−sign(x₀)‖x‖ e₁` is applied on both sides of the trailing block,
//!    `A ← A − v wᵀ − w vᵀ` with `p = β A v`, `w = p − (β pᵀv / 2) v`. `T = QᵀAQ` has A's
//!    eigenvalues.
//! 2. **Implicit QL iterations with Wilkinson's shift** on the tridiagonal `T` (the EISPACK
//!    routine `tql1`; Golub and Van Loan, section 8.3.3): an off-diagonal entry below
//!    `ε (|d_m| + |d_{m+1}|)` splits the matrix; on each unreduced block a shifted QL sweep of
//!    plane rotations chases the bulge from its bottom to its top, until its top off-diagonal
//!    entry vanishes, leaving d_l an eigenvalue.
//!
//! The eigenvalues come out with an error of order `ε ‖A‖`: a Gram matrix's smallest, and so
//! a condition number, to a relative `ε cond²` (10⁻⁸ at a condition number of 10⁴).

/// The most QL sweeps for one eigenvalue; typically 2 or 3 are enough.
const MAX_SWEEPS: usize = 60;

/// The eigenvalues of the symmetric `n × n` matrix `a` (row-major; its lower triangle is read
/// and overwritten), in increasing order.
#[must_use]
pub fn symmetric_eigenvalues(a: &mut [f64], n: usize) -> Vec<f64> {
    let (mut d, mut e) = tridiagonalise(a, n);
    ql(&mut d, &mut e);
    d.sort_by(f64::total_cmp);
    d
}

/// The diagonal and the off-diagonal (`e[k]` between rows k and k + 1; `e[n−1] = 0`) of a
/// tridiagonal matrix similar to `a`.
fn tridiagonalise(a: &mut [f64], n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut e = vec![0.0; n];
    let (mut v, mut p) = (vec![0.0; n], vec![0.0; n]);
    for k in 0..n.saturating_sub(2) {
        let x = |i: usize| a[i * n + k];
        let norm = (k + 1..n).map(|i| x(i) * x(i)).sum::<f64>().sqrt();
        if norm == 0.0 {
            continue;
        }
        let alpha = if x(k + 1) > 0.0 { -norm } else { norm };
        // v = x − α e₁, β = 2 / vᵀv = 1 / (α² − α x₀).
        for (i, vi) in v.iter_mut().enumerate().skip(k + 1) {
            *vi = x(i);
        }
        v[k + 1] -= alpha;
        let beta = 1.0 / (alpha * alpha - alpha * x(k + 1));
        // p = β A v over the trailing block, from its lower triangle.
        for i in k + 1..n {
            let row: f64 = (k + 1..n).map(|j| a[i.max(j) * n + i.min(j)] * v[j]).sum();
            p[i] = beta * row;
        }
        let half = 0.5 * beta * (k + 1..n).map(|i| p[i] * v[i]).sum::<f64>();
        for i in k + 1..n {
            p[i] -= half * v[i];
        }
        for i in k + 1..n {
            for j in k + 1..=i {
                a[i * n + j] -= v[i] * p[j] + p[i] * v[j];
            }
        }
        a[(k + 1) * n + k] = alpha;
    }
    let d = (0..n).map(|k| a[k * n + k]).collect();
    for k in 0..n.saturating_sub(1) {
        e[k] = a[(k + 1) * n + k];
    }
    (d, e)
}

/// Diagonalises the symmetric tridiagonal matrix `(d, e)` in place: `d` becomes its
/// eigenvalues.
fn ql(d: &mut [f64], e: &mut [f64]) {
    let n = d.len();
    for l in 0..n {
        for _sweep in 0..MAX_SWEEPS {
            // The first negligible off-diagonal entry at or below l.
            let m = (l..n - 1)
                .find(|&m| e[m].abs() <= f64::EPSILON * (d[m].abs() + d[m + 1].abs()))
                .unwrap_or(n - 1);
            if m == l {
                break;
            }
            sweep(d, e, l, m);
        }
    }
}

/// One shifted QL sweep on the unreduced block `l..=m`.
fn sweep(d: &mut [f64], e: &mut [f64], l: usize, m: usize) {
    // Wilkinson's shift: the eigenvalue of the top 2 × 2 block nearer d[l].
    let mut g = (d[l + 1] - d[l]) / (2.0 * e[l]);
    let r = g.hypot(1.0);
    g = d[m] - d[l] + e[l] / (g + r.copysign(g));
    let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
    for i in (l..m).rev() {
        let f = s * e[i];
        let b = c * e[i];
        let r = f.hypot(g);
        e[i + 1] = r;
        if r == 0.0 {
            // The rotation underflowed: the block splits at i; sweep again from the top.
            d[i + 1] -= p;
            e[m] = 0.0;
            return;
        }
        s = f / r;
        c = g / r;
        g = d[i + 1] - p;
        let t = (d[i] - g) * s + 2.0 * c * b;
        p = s * t;
        d[i + 1] = g + p;
        g = c * t - b;
    }
    d[l] -= p;
    e[l] = g;
    e[m] = 0.0;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::singular::singular_values;

    /// `Q diag(λ) Qᵀ` with Q a product of plane rotations: its eigenvalues are λ.
    fn rotated(lambda: &[f64]) -> Vec<f64> {
        let n = lambda.len();
        let mut a = vec![0.0; n * n];
        for (k, l) in lambda.iter().enumerate() {
            a[k * n + k] = *l;
        }
        // Rotate rows and columns (i, j) by an angle, for several pairs.
        for (step, (i, j)) in [(0, 1), (1, 3), (0, 4), (2, 4), (3, 4), (1, 2)]
            .iter()
            .enumerate()
        {
            let (i, j) = (i % n, j % n);
            if i == j {
                continue;
            }
            let (s, c) = (0.4 + 0.7 * step as f64).sin_cos();
            for k in 0..n {
                let (x, y) = (a[i * n + k], a[j * n + k]);
                a[i * n + k] = c * x - s * y;
                a[j * n + k] = s * x + c * y;
            }
            for k in 0..n {
                let (x, y) = (a[k * n + i], a[k * n + j]);
                a[k * n + i] = c * x - s * y;
                a[k * n + j] = s * x + c * y;
            }
        }
        a
    }

    #[test]
    fn the_eigenvalues_of_a_rotated_diagonal() {
        let lambda = [1e-6, -3.0, 0.5, 2.0, 1e4];
        let mut a = rotated(&lambda);
        let got = symmetric_eigenvalues(&mut a, 5);
        let mut want = lambda.to_vec();
        want.sort_by(f64::total_cmp);
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() <= 1e-11 * 1e4, "{got:?}");
        }
    }

    #[test]
    fn repeated_eigenvalues_and_small_matrices() {
        let mut a = rotated(&[2.0, 2.0, 2.0, 7.0, 7.0]);
        let got = symmetric_eigenvalues(&mut a, 5);
        for (g, w) in got.iter().zip([2.0, 2.0, 2.0, 7.0, 7.0]) {
            assert!((g - w).abs() < 1e-13, "{got:?}");
        }
        assert_eq!(symmetric_eigenvalues(&mut [3.0], 1), [3.0]);
        // [[2, 1], [1, 2]]: 1 and 3.
        let got = symmetric_eigenvalues(&mut [2.0, 1.0, 1.0, 2.0], 2);
        assert!((got[0] - 1.0).abs() < 1e-15 && (got[1] - 3.0).abs() < 1e-15);
        assert!(symmetric_eigenvalues(&mut [], 0).is_empty());
    }

    /// The eigenvalues of `AᵀA` are the squares of A's singular values, which the one-sided
    /// Jacobi rotations of `identify` find by another route.
    #[test]
    fn a_gram_matrix_s_eigenvalues_are_the_squared_singular_values() {
        let n = 12;
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        // Columns scaled over four decades, as a regressor's are.
        let a: Vec<f64> = (0..n * n)
            .map(|k| uniform() * 10f64.powf((k % n) as f64 / 3.0))
            .collect();
        let mut gram = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                gram[i * n + j] = (0..n).map(|k| a[k * n + i] * a[k * n + j]).sum();
            }
        }
        let largest = gram.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let eigen = symmetric_eigenvalues(&mut gram, n);
        let mut singular = singular_values(&a, n);
        singular.reverse();
        for (l, s) in eigen.iter().zip(&singular) {
            assert!(
                (l - s * s).abs() <= 1e-13 * largest,
                "{eigen:?} {singular:?}"
            );
        }
    }
}
