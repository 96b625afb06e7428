//! The dense LDLᵀ factorization of the mass matrix, `M = L D Lᵀ` (L unit lower triangular,
//! D diagonal), unrolled: for column j,
//! `d_j = M_jj − Σ_{k<j} W_jk L_jk`, `W_ij = M_ij − Σ_{k<j} W_ik L_jk`, `L_ij = W_ij / d_j`
//! (i > j, `W_ij = L_ij d_j`); then `M x = b` by `L y = b`, `z = D⁻¹ y`, `Lᵀ x = z`, and
//! `M⁻¹ = L⁻ᵀ D⁻¹ L⁻¹`. A serial chain's M is dense, so Featherstone's sparse LTL is this plain
//! form. The only divisions are the n reciprocals of the pivots; M is positive definite exactly
//! when every pivot is positive, which the generated code checks.

use super::Scalar;

/// `M = L D Lᵀ`.
#[derive(Clone, Debug)]
pub struct Ldlt<S> {
    /// `L_ij` for `j < i` (row i holds i entries; the unit diagonal is not stored).
    pub lower: Vec<Vec<S>>,
    /// The pivots `d_j`.
    pub pivots: Vec<S>,
    /// `1 / d_j`.
    pub inverse_pivots: Vec<S>,
}

/// The LDLᵀ factors of the symmetric `m`; `recip` is `1 / x` in the scalar.
pub fn ldlt<S: Scalar>(m: &[Vec<S>], recip: impl Fn(S) -> S) -> Ldlt<S> {
    let n = m.len();
    // w[i][k] = L_ik d_k, k < i.
    let mut w: Vec<Vec<S>> = vec![Vec::new(); n];
    let mut lower: Vec<Vec<S>> = vec![Vec::new(); n];
    let (mut pivots, mut inverse_pivots) = (Vec::new(), Vec::new());
    for j in 0..n {
        let d = (0..j).fold(m[j][j], |acc, k| acc - w[j][k] * lower[j][k]);
        let r = recip(d);
        for i in j + 1..n {
            let wij = (0..j).fold(m[i][j], |acc, k| acc - w[i][k] * lower[j][k]);
            w[i].push(wij);
            lower[i].push(wij * r);
        }
        pivots.push(d);
        inverse_pivots.push(r);
    }
    Ldlt {
        lower,
        pivots,
        inverse_pivots,
    }
}

impl<S: Scalar> Ldlt<S> {
    /// `x = M⁻¹ b`.
    #[must_use]
    pub fn solve(&self, b: &[S]) -> Vec<S> {
        let n = b.len();
        // L y = b, then z = D⁻¹ y.
        let mut y: Vec<S> = Vec::with_capacity(n);
        for (row, &bi) in self.lower.iter().zip(b) {
            let yi = row.iter().zip(&y).fold(bi, |acc, (&l, &yk)| acc - l * yk);
            y.push(yi);
        }
        let mut x: Vec<S> = y
            .iter()
            .zip(&self.inverse_pivots)
            .map(|(&yi, &r)| yi * r)
            .collect();
        // Lᵀ x = z, from the last row up.
        for i in (0..n).rev() {
            x[i] = (i + 1..n).fold(x[i], |acc, k| acc - self.lower[k][i] * x[k]);
        }
        x
    }

    /// `M⁻¹ = L⁻ᵀ D⁻¹ L⁻¹`, symmetric: `(M⁻¹)_ij = Σ_{k ≥ max(i, j)} X_ki X_kj / d_k` with
    /// `X = L⁻¹` (unit lower triangular).
    #[must_use]
    #[allow(clippy::needless_range_loop)]
    pub fn inverse(&self) -> Vec<Vec<S>> {
        let n = self.pivots.len();
        let Some(&first) = self.pivots.first() else {
            return Vec::new();
        };
        let (zero, one) = (first.zero(), first.one());
        // X = L⁻¹ by forward substitution, column by column: X_ij = −Σ_{j≤k<i} L_ik X_kj.
        let mut x = vec![vec![zero; n]; n];
        for j in 0..n {
            x[j][j] = one;
            for i in j + 1..n {
                // Read through indices: row i of X is written while rows k < i are read.
                x[i][j] =
                    (j + 1..i).fold(-self.lower[i][j], |acc, k| acc - self.lower[i][k] * x[k][j]);
            }
        }
        let mut inverse = vec![vec![zero; n]; n];
        for i in 0..n {
            for j in i..n {
                // k from the last row, so that the sums start from the pivots' reciprocals.
                let sum = (j..n).rev().fold(zero, |acc, k| {
                    acc + x[k][i] * (self.inverse_pivots[k] * x[k][j])
                });
                inverse[i][j] = sum;
                inverse[j][i] = sum;
            }
        }
        inverse
    }
}

#[cfg(test)]
mod tests {
    use super::ldlt;

    /// An independent check: the factors multiply back to M, the solution satisfies M x = b
    /// and M M⁻¹ = I, on a symmetric positive definite 5 × 5 matrix (AᵀA + I).
    #[test]
    fn factors_solve_and_invert() {
        let n = 5;
        let a: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| ((i * 7 + j * 3) % 5) as f64 * 0.3 - 0.5)
                    .collect()
            })
            .collect();
        let m: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| (0..n).map(|k| a[k][i] * a[k][j]).sum::<f64>() + f64::from(i == j))
                    .collect()
            })
            .collect();
        let f = ldlt(&m, |x| 1.0 / x);
        let l = |i: usize, k: usize| match i.cmp(&k) {
            std::cmp::Ordering::Greater => f.lower[i][k],
            std::cmp::Ordering::Equal => 1.0,
            std::cmp::Ordering::Less => 0.0,
        };
        let inverse = f.inverse();
        let b = [0.3, -1.2, 0.7, 2.0, -0.1];
        let x = f.solve(&b);
        for i in 0..n {
            let mx: f64 = (0..n).map(|j| m[i][j] * x[j]).sum();
            assert!((mx - b[i]).abs() < 1e-12, "row {i}: {mx} vs {}", b[i]);
            for j in 0..n {
                let ldl: f64 = (0..n).map(|k| l(i, k) * f.pivots[k] * l(j, k)).sum();
                assert!((ldl - m[i][j]).abs() < 1e-12);
                let identity: f64 = (0..n).map(|k| m[i][k] * inverse[k][j]).sum();
                assert!((identity - f64::from(i == j)).abs() < 1e-12);
            }
        }
        assert!(f.pivots.iter().all(|&d| d > 0.0));
    }
}
