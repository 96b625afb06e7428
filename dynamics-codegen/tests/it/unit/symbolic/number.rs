use dynamics_codegen::symbolic::Number;

#[test]
fn decimals_are_exact() {
    assert_eq!(Number::parse_decimal("0.4318"), Number::ratio(4318, 10000));
    assert_eq!(Number::parse_decimal("-1.5e-3"), Number::ratio(-15, 10000));
    assert_eq!(Number::parse_decimal("12"), Some(Number::int(12)));
    assert_eq!(Number::parse_decimal("1e3"), Some(Number::int(1000)));
    assert_eq!(Number::from_f64(0.1), Number::ratio(1, 10).unwrap());
    assert_eq!(
        Number::from_f64(0.6718299999999999),
        Number::ratio(6718299999999999, 10_000_000_000_000_000).unwrap()
    );
    assert_eq!(Number::parse_decimal("abc"), None);
    assert_eq!(Number::parse_decimal("."), None);
}

/// Reduction on either side of 64 bits (where the gcd changes method): `2⁷⁰·3 / 2⁷⁰·6` is
/// `1/2`, `(2⁶⁴ − 1)·2 / 4` is `(2⁶⁴ − 1)/2` (odd numerator), signs to the numerator.
#[test]
fn reduction_across_64_bits() {
    let big = 1i128 << 70;
    assert_eq!(Number::ratio(3 * big, 6 * big), Number::ratio(1, 2));
    assert_eq!(
        Number::ratio(3 * big, 6 * big),
        Some(Number::Rational(1, 2))
    );
    let max = i128::from(u64::MAX);
    assert_eq!(Number::ratio(2 * max, 4), Some(Number::Rational(max, 2)));
    assert_eq!(Number::ratio(-6, -4), Some(Number::Rational(3, 2)));
    assert_eq!(Number::ratio(0, -7), Some(Number::ZERO));
    assert_eq!(Number::ratio(5, 0), None);
    // (2⁷⁰/3)·(9/2⁶⁹) = 6, reduced crosswise before multiplying.
    let a = Number::ratio(big, 3).unwrap();
    let b = Number::ratio(9, big / 2).unwrap();
    assert_eq!(a * b, Number::int(6));
    assert_eq!(
        Number::int(-4) * Number::ratio(3, 8).unwrap(),
        Number::ratio(-3, 2).unwrap()
    );
    // Integers: exact, and past i128 a float, as for any rational.
    assert_eq!(Number::int(-4) * Number::int(6), Number::int(-24));
    assert_eq!(Number::int(7) + Number::int(-9), Number::int(-2));
    let huge = Number::Rational(i128::MAX, 1);
    assert!(!(huge + Number::ONE).is_exact());
    assert!(!(huge * Number::int(2)).is_exact());
}

#[test]
fn arithmetic_is_exact_and_falls_back_to_float() {
    let third = Number::ratio(1, 3).unwrap();
    assert_eq!(third + third + third, Number::ONE);
    assert_eq!(third * Number::int(3), Number::ONE);
    assert!((third - third).is_zero());
    assert_eq!(third.recip(), Some(Number::int(3)));
    let big = Number::ratio(1, 100_000_000_000_000_000_000).unwrap();
    let tiny = big * big;
    assert!(!tiny.is_exact());
    assert!((tiny.to_f64() - 1e-40).abs() < 1e-54);
}
