use dynamics_codegen::check::eigenvalues;

#[test]
fn eigenvalues_of_known_matrices() {
    // [[2, 1, 0], [1, 2, 0], [0, 0, 5]] has eigenvalues 1, 3, 5.
    let l = eigenvalues([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]]);
    for (a, b) in l.iter().zip([1.0, 3.0, 5.0]) {
        assert!((a - b).abs() < 1e-12, "{l:?}");
    }
    // [[2, -1, 0], [-1, 2, -1], [0, -1, 2]]: 2 - √2, 2, 2 + √2.
    let l = eigenvalues([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]]);
    let r = std::f64::consts::SQRT_2;
    for (a, b) in l.iter().zip([2.0 - r, 2.0, 2.0 + r]) {
        assert!((a - b).abs() < 1e-12, "{l:?}");
    }
}
