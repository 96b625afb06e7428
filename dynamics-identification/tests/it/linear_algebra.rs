//! Singular values, symmetric eigenvalues and a triangle's inverse, against known matrices.

use dynamics_identification::linear_algebra::{inverse, singular_values, symmetric_eigenvalues};

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
    let a = rotated(&lambda);
    let got = symmetric_eigenvalues(&a, 5);
    let mut want = lambda.to_vec();
    want.sort_by(f64::total_cmp);
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() <= 1e-11 * 1e4, "{got:?}");
    }
}

#[test]
fn repeated_eigenvalues_and_small_matrices() {
    let a = rotated(&[2.0, 2.0, 2.0, 7.0, 7.0]);
    let got = symmetric_eigenvalues(&a, 5);
    for (g, w) in got.iter().zip([2.0, 2.0, 2.0, 7.0, 7.0]) {
        assert!((g - w).abs() < 1e-13, "{got:?}");
    }
    assert_eq!(symmetric_eigenvalues(&[3.0], 1), [3.0]);
    // [[2, 1], [1, 2]]: 1 and 3.
    let got = symmetric_eigenvalues(&[2.0, 1.0, 1.0, 2.0], 2);
    assert!((got[0] - 1.0).abs() < 1e-15 && (got[1] - 3.0).abs() < 1e-15);
    assert!(symmetric_eigenvalues(&[], 0).is_empty());
}

/// The eigenvalues of `AᵀA` are the squares of A's singular values, found by another
/// route.
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
    let eigen = symmetric_eigenvalues(&gram, n);
    let mut singular = singular_values(&a, n);
    singular.reverse();
    for (l, s) in eigen.iter().zip(&singular) {
        assert!(
            (l - s * s).abs() <= 1e-13 * largest,
            "{eigen:?} {singular:?}"
        );
    }
}

#[test]
fn the_inverse_of_a_triangle() {
    let r = [2.0, 1.0, -1.0, 0.0, 4.0, 2.0, 0.0, 0.0, 0.5];
    let inv = inverse(&r, 3);
    for i in 0..3 {
        for j in 0..3 {
            let product: f64 = (0..3).map(|k| r[i * 3 + k] * inv[k * 3 + j]).sum();
            let unit = if i == j { 1.0 } else { 0.0 };
            assert!((product - unit).abs() < 1e-15, "{i} {j}");
        }
    }
}
