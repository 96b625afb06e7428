//! The dense linear algebra of identification and excitation, by nalgebra, on the row-major
//! slices the factors are kept in: singular values (bidiagonalisation and implicit QR),
//! symmetric eigenvalues and eigenvectors (tridiagonalisation and implicit QR), triangular
//! solves.
//!
//! What nalgebra does not do stays by hand, where it is used: the triangular factor of rows
//! that arrive in blocks ([`crate::identify::householder`]) and the rank-revealing QR that takes
//! the columns in the model's order ([`crate::identify::rank`]).

use nalgebra::{DMatrix, DVector, Matrix3, Matrix4};

/// The singular values of the `n × n` matrix `a` (row-major), largest first.
#[must_use]
pub fn singular_values(a: &[f64], n: usize) -> Vec<f64> {
    if n == 0 {
        return Vec::new();
    }
    let mut values: Vec<f64> = DMatrix::from_row_slice(n, n, a)
        .singular_values()
        .iter()
        .copied()
        .collect();
    values.sort_by(|x, y| y.total_cmp(x));
    values
}

/// The eigenvalues of the symmetric `n × n` matrix `a` (row-major; its lower triangle is
/// read), in increasing order.
#[must_use]
pub fn symmetric_eigenvalues(a: &[f64], n: usize) -> Vec<f64> {
    if n == 0 {
        // nalgebra refuses an empty matrix.
        return Vec::new();
    }
    let lower = DMatrix::from_fn(n, n, |i, j| a[i.max(j) * n + i.min(j)]);
    let mut values: Vec<f64> = lower.symmetric_eigenvalues().iter().copied().collect();
    values.sort_by(f64::total_cmp);
    values
}

/// The eigenvalues of a symmetric 4 × 4 matrix and their unit eigenvectors (`vectors[k]` for
/// `values[k]`), in no particular order.
#[must_use]
pub fn eigen4(a: [[f64; 4]; 4]) -> ([f64; 4], [[f64; 4]; 4]) {
    let eigen = Matrix4::from_fn(|i, j| a[i][j]).symmetric_eigen();
    let values = std::array::from_fn(|k| eigen.eigenvalues[k]);
    let vectors = std::array::from_fn(|k| std::array::from_fn(|i| eigen.eigenvectors[(i, k)]));
    (values, vectors)
}

/// [`eigen4`] of a symmetric 3 × 3 matrix.
#[must_use]
pub fn eigen3(a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let eigen = Matrix3::from_fn(|i, j| a[i][j]).symmetric_eigen();
    let values = std::array::from_fn(|k| eigen.eigenvalues[k]);
    let vectors = std::array::from_fn(|k| std::array::from_fn(|i| eigen.eigenvectors[(i, k)]));
    (values, vectors)
}

/// Solves `R x = b` for upper-triangular `R` (row-major, `n × n`).
#[must_use]
pub fn back_substitute(r: &[f64], n: usize, b: &[f64]) -> Vec<f64> {
    let r = DMatrix::from_row_slice(n, n, r);
    let mut x = DVector::from_column_slice(b);
    r.solve_upper_triangular_mut(&mut x);
    x.as_slice().to_vec()
}

/// `R⁻¹` of an upper-triangular `R` (row-major, `n × n`), upper triangular, row-major.
#[must_use]
pub fn inverse(r: &[f64], n: usize) -> Vec<f64> {
    let r = DMatrix::from_row_slice(n, n, r);
    let mut inv = DMatrix::identity(n, n);
    r.solve_upper_triangular_mut(&mut inv);
    // Row-major: the transpose's column-major storage.
    inv.transpose().as_slice().to_vec()
}
