use dynamics_codegen::symbolic::modular::Fp;
use dynamics_codegen::symbolic::Number;
use dynamics_codegen::trace::base_parameters::coefficients::{exact_or_float, least_squares};

#[test]
fn solves_an_overdetermined_system() {
    // Rows of x + 2y = b with b exact for x = 3, y = −1.
    let a = vec![
        vec![1.0, 0.0],
        vec![0.0, 1.0],
        vec![1.0, 1.0],
        vec![2.0, 1.0],
    ];
    let b = vec![3.0, -1.0, 2.0, 5.0];
    let x = least_squares(a, b);
    assert!((x[0] - 3.0).abs() < 1e-14 && (x[1] + 1.0).abs() < 1e-14);
}

#[test]
fn recovers_decimals() {
    // 0.4318² = 0.18645124, exactly.
    let residue = Fp::int(4318 * 4318) * Fp::int(100_000_000).recip().unwrap();
    assert_eq!(
        exact_or_float(residue, 0.186_451_24),
        Number::ratio(18_645_124, 100_000_000).unwrap()
    );
    // A residue that disagrees with the float keeps the float.
    assert_eq!(exact_or_float(Fp::int(3), 0.5), Number::Float(0.5));
}
