//! The streamed Householder factor: least squares through it, a zero column.

use dynamics_identification::identify::householder::Triangle;
use dynamics_identification::linear_algebra::back_substitute;

/// A 7 × 3 matrix (a quadratic's basis at 7 points, and a right-hand side) whose normal
/// equations are solved by hand below.
fn rows() -> Vec<[f64; 4]> {
    (0..7)
        .map(|i| {
            let x = f64::from(i) - 3.0;
            // y = 1 + 2x − 0.5x² plus a residual orthogonal to 1, x, x².
            let wiggle = [-1.0, 6.0, -15.0, 20.0, -15.0, 6.0, -1.0][i as usize];
            [1.0, x, x * x, 1.0 + 2.0 * x - 0.5 * x * x + 0.01 * wiggle]
        })
        .collect()
}

#[test]
fn least_squares_through_the_factor() {
    // The wiggle is the 6th difference of a unit impulse, orthogonal to every polynomial of
    // degree below 6: the fit is exactly 1 + 2x − 0.5x², its residual 0.01 ‖wiggle‖.
    for block in [1, 2, 3, 100] {
        let mut t = Triangle::new(4, block);
        for row in rows() {
            t.push(&row);
        }
        assert_eq!(t.rows(), 7);
        let r = t.factor().to_vec();
        let r3: Vec<f64> = (0..3).flat_map(|i| r[i * 4..i * 4 + 3].to_vec()).collect();
        let z: Vec<f64> = (0..3).map(|i| r[i * 4 + 3]).collect();
        let x = back_substitute(&r3, 3, &z);
        for (got, want) in x.iter().zip([1.0, 2.0, -0.5]) {
            assert!((got - want).abs() < 1e-13, "{block}: {x:?}");
        }
        let residual: f64 = 0.01 * (1.0f64 + 36.0 + 225.0 + 400.0 + 225.0 + 36.0 + 1.0).sqrt();
        assert!((r[15].abs() - residual).abs() < 1e-13, "{}", r[15]);
        // RᵀR = AᵀA: the sums of 1, x², x⁴ over x = −3..3 are 7, 28, 196.
        let gram = |a: usize, b: usize| (0..4).map(|i| r[i * 4 + a] * r[i * 4 + b]).sum::<f64>();
        assert!((gram(0, 0) - 7.0).abs() < 1e-12 && (gram(1, 1) - 28.0).abs() < 1e-12);
        assert!((gram(2, 2) - 196.0).abs() < 1e-11 && gram(0, 1).abs() < 1e-12);
    }
}

#[test]
fn a_zero_column_is_left_alone() {
    let mut t = Triangle::new(2, 4);
    t.push(&[0.0, 3.0]);
    t.push(&[0.0, 4.0]);
    let r = t.factor();
    assert_eq!(r[0], 0.0);
    assert!((r[3].abs() - 5.0).abs() < 1e-15);
}
