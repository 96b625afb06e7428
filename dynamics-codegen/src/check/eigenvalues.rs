//! The eigenvalues of a symmetric 3×3 matrix (an inertia tensor's principal moments) by cyclic
//! Jacobi rotations: each rotation `A ← Jᵀ A J` zeroes one off-diagonal entry, and the sweeps
//! repeat until the off-diagonal part is negligible (at most 64 sweeps).

/// The eigenvalues of a symmetric 3×3 matrix, ascending (cyclic Jacobi rotations, a bounded
/// number of sweeps).
#[must_use]
pub fn eigenvalues(mut a: [[f64; 3]; 3]) -> [f64; 3] {
    for _ in 0..64 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let diag = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= f64::EPSILON * diag * 1e-3 || off == 0.0 || !off.is_finite() {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = 0.5 * (2.0 * a[p][q]).atan2(a[q][q] - a[p][p]);
            let (s, c) = theta.sin_cos();
            // A ← Jᵀ A J with J the rotation in the (p, q) plane.
            for row in &mut a {
                let (x, y) = (row[p], row[q]);
                row[p] = c * x - s * y;
                row[q] = s * x + c * y;
            }
            let (row_p, row_q) = (a[p], a[q]);
            a[p] = std::array::from_fn(|k| c * row_p[k] - s * row_q[k]);
            a[q] = std::array::from_fn(|k| s * row_p[k] + c * row_q[k]);
        }
    }
    let mut l = [a[0][0], a[1][1], a[2][2]];
    l.sort_by(f64::total_cmp);
    l
}
