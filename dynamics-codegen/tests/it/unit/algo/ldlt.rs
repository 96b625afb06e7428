use dynamics_codegen::algo::Ldlt;

/// An independent check: the factors multiply back to M, the solutions satisfy M x = b and
/// M X = B, and M M⁻¹ = I, on a symmetric positive definite 5 × 5 matrix (AᵀA + I).
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
    let f = Ldlt::new(&m);
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
    let columns = [
        [0.3, 1.0],
        [-1.2, 0.0],
        [0.7, -2.5],
        [2.0, 0.4],
        [-0.1, 0.9],
    ];
    let rows: Vec<Vec<f64>> = columns.iter().map(|r| r.to_vec()).collect();
    let solved = f.solve_columns(&rows);
    for i in 0..n {
        for c in 0..2 {
            let mx: f64 = (0..n).map(|j| m[i][j] * solved[j][c]).sum();
            assert!((mx - columns[i][c]).abs() < 1e-12, "({i}, {c}): {mx}");
        }
    }
    assert!(f.pivots.iter().all(|&d| d > 0.0));
}

/// Factored from the tips, a tree's M (joint 0 carrying 1 and 2, joint 2 carrying 3)
/// keeps its zeros in L, solves `M x = b` and inverts M.
#[test]
#[allow(clippy::needless_range_loop)]
fn from_the_tips_keeps_a_trees_zeros() {
    let m = [
        [4.0, 1.0, 0.5, 0.3],
        [1.0, 3.0, 0.0, 0.0],
        [0.5, 0.0, 2.5, 0.4],
        [0.3, 0.0, 0.4, 2.0],
    ]
    .map(Vec::from)
    .to_vec();
    let f = Ldlt::from_the_tips(&m);
    // In reverse order, row k of L is (the reversed) joint 3 − k: joint 1's row (k = 2)
    // reaches joint 0 alone, never joints 2 or 3.
    assert_eq!(f.lower[2], vec![0.0, 0.0]);
    let b = [0.3, -1.2, 0.7, 2.0];
    let x = f.solve(&b);
    let inverse = f.inverse();
    for i in 0..4 {
        let mx: f64 = (0..4).map(|j| m[i][j] * x[j]).sum();
        assert!((mx - b[i]).abs() < 1e-12, "row {i}: {mx} vs {}", b[i]);
        for j in 0..4 {
            let identity: f64 = (0..4).map(|k| m[i][k] * inverse[k][j]).sum();
            assert!((identity - f64::from(i == j)).abs() < 1e-12);
        }
    }
}
