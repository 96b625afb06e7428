//! The dense LDLᵀ factorization of the mass matrix, `M = L D Lᵀ` (L unit lower triangular,
//! D diagonal), unrolled: for column j,
//! `d_j = M_jj − Σ_{k<j} W_jk L_jk`, `W_ij = M_ij − Σ_{k<j} W_ik L_jk`, `L_ij = W_ij / d_j`
//! (i > j, `W_ij = L_ij d_j`); then `M x = b` by `L y = b`, `z = D⁻¹ y`, `Lᵀ x = z`, and
//! `M⁻¹ = L⁻ᵀ D⁻¹ L⁻¹`. A serial chain's M is dense, so Featherstone's sparse LTL is this plain
//! form. The only divisions are the n reciprocals of the pivots; M is positive definite exactly
//! when every pivot is positive, which the generated code checks.
//!
//! A kinematic tree's M is zero wherever neither joint is an ancestor of the other; eliminating
//! from the first joint fills those zeros in. Featherstone's `M = Lᵀ D L` (*Rigid Body Dynamics
//! Algorithms* §6.5) eliminates from the last joint instead, where joint k's column reaches only
//! its ancestors, which are all related to each other: no fill-in, L keeps M's zeros. It is
//! the form above on M with its joints in reverse order, `P M P = (P Lᵀ P) (P D P) (P L P)`
//! with P the reversal ([`Ldlt::from_the_tips`]); the zeros of M, exact in the trace, fold
//! every product that would have filled them.

use super::Scalar;

/// `M = L D Lᵀ`, factored once ([`Ldlt::new`]), then solved for one right-hand side
/// ([`Ldlt::solve`]), for several ([`Ldlt::solve_columns`]), or inverted ([`Ldlt::inverse`]).
#[derive(Clone, Debug)]
pub struct Ldlt<S> {
    /// `L_ij` for `j < i` (row i holds i entries; the unit diagonal is not stored).
    pub lower: Vec<Vec<S>>,
    /// The pivots `d_j`: M is positive definite exactly when all are positive.
    pub pivots: Vec<S>,
    /// `1 / d_j`.
    pub inverse_pivots: Vec<S>,
    /// Whether these are the factors of M with its joints in reverse order (Featherstone's
    /// `Lᵀ D L`); the solutions and the inverse are in M's order either way.
    pub reversed: bool,
}

impl<S: Copy> Ldlt<S> {
    /// The same factors, each entry through `f` (a symbolic factor to its node ids and back).
    #[must_use]
    pub fn map<U>(&self, f: impl Fn(S) -> U) -> Ldlt<U> {
        Ldlt {
            lower: self
                .lower
                .iter()
                .map(|row| row.iter().map(|&x| f(x)).collect())
                .collect(),
            pivots: self.pivots.iter().map(|&x| f(x)).collect(),
            inverse_pivots: self.inverse_pivots.iter().map(|&x| f(x)).collect(),
            reversed: self.reversed,
        }
    }
}

impl<S: Scalar> Ldlt<S> {
    /// The factors of the symmetric `m` (its lower triangle is read), n × n.
    #[must_use]
    pub fn new(m: &[Vec<S>]) -> Ldlt<S> {
        let n = m.len();
        // w[i][k] = L_ik d_k, k < i.
        let mut w: Vec<Vec<S>> = vec![Vec::new(); n];
        let mut lower: Vec<Vec<S>> = vec![Vec::new(); n];
        let (mut pivots, mut inverse_pivots) = (Vec::new(), Vec::new());
        for j in 0..n {
            let d = (0..j).fold(m[j][j], |acc, k| acc - w[j][k] * lower[j][k]);
            let r = d.recip();
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
            reversed: false,
        }
    }

    /// Featherstone's `M = Lᵀ D L`: the factors of `m` with its rows and columns in reverse
    /// order (see the module documentation), for a tree's M.
    #[must_use]
    pub fn from_the_tips(m: &[Vec<S>]) -> Ldlt<S> {
        let reversed: Vec<Vec<S>> = m
            .iter()
            .rev()
            .map(|row| row.iter().rev().copied().collect())
            .collect();
        Ldlt {
            reversed: true,
            ..Ldlt::new(&reversed)
        }
    }

    /// `x = M⁻¹ b`.
    #[must_use]
    pub fn solve(&self, b: &[S]) -> Vec<S> {
        if self.reversed {
            let b: Vec<S> = b.iter().rev().copied().collect();
            let mut x = self.solve_in_order(&b);
            x.reverse();
            return x;
        }
        self.solve_in_order(b)
    }

    /// [`Ldlt::solve`] in the factors' own order.
    fn solve_in_order(&self, b: &[S]) -> Vec<S> {
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

    /// `y = L⁻¹ b`, in the factors' order (reversed where they are), `b` in M's: the first
    /// half of [`Ldlt::solve`]. For two such `y` and `z`, `bᵀ M⁻¹ c = Σ_k y_k z_k / d_k`; from
    /// the tips, a column that is zero outside one branch and the root stays so (no fill-in).
    #[must_use]
    pub fn forward_substitution(&self, b: &[S]) -> Vec<S> {
        let mut y: Vec<S> = Vec::with_capacity(b.len());
        let b: Vec<S> = if self.reversed {
            b.iter().rev().copied().collect()
        } else {
            b.to_vec()
        };
        for (row, &bi) in self.lower.iter().zip(&b) {
            let yi = row.iter().zip(&y).fold(bi, |acc, (&l, &yk)| acc - l * yk);
            y.push(yi);
        }
        y
    }

    /// `x = L⁻ᵀ z`, `z` in the factors' order, `x` in M's: the second half of [`Ldlt::solve`]
    /// (`z = D⁻¹ y` for `y` of [`Ldlt::forward_substitution`] gives `x = M⁻¹ b`).
    #[must_use]
    pub fn back_substitution(&self, z: &[S]) -> Vec<S> {
        let n = z.len();
        let mut x = z.to_vec();
        for i in (0..n).rev() {
            x[i] = (i + 1..n).fold(x[i], |acc, k| acc - self.lower[k][i] * x[k]);
        }
        if self.reversed {
            x.reverse();
        }
        x
    }

    /// `X = M⁻¹ B` for `B` given by its rows (n × k, any k): each column solved with the same
    /// factors.
    #[must_use]
    pub fn solve_columns(&self, b: &[Vec<S>]) -> Vec<Vec<S>> {
        let k = b.first().map_or(0, Vec::len);
        let columns: Vec<Vec<S>> = (0..k)
            .map(|j| self.solve(&b.iter().map(|row| row[j]).collect::<Vec<S>>()))
            .collect();
        (0..b.len())
            .map(|i| columns.iter().map(|column| column[i]).collect())
            .collect()
    }

    /// `M⁻¹ = L⁻ᵀ D⁻¹ L⁻¹`, symmetric: `(M⁻¹)_ij = Σ_{k ≥ max(i, j)} X_ki X_kj / d_k` with
    /// `X = L⁻¹` (unit lower triangular).
    #[must_use]
    pub fn inverse(&self) -> Vec<Vec<S>> {
        let mut inverse = self.inverse_in_order();
        if self.reversed {
            inverse.reverse();
            for row in &mut inverse {
                row.reverse();
            }
        }
        inverse
    }

    /// [`Ldlt::inverse`] in the factors' own order.
    #[allow(clippy::needless_range_loop)]
    fn inverse_in_order(&self) -> Vec<Vec<S>> {
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
