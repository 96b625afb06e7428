use dynamics_codegen::symbolic::Number;
use dynamics_codegen::trace::tracer::exact_sin_cos;

#[test]
fn exact_angles() {
    let half = Number::ratio(1, 2).unwrap();
    assert_eq!(exact_sin_cos(half), Some((Number::ONE, Number::ZERO)));
    assert_eq!(
        exact_sin_cos(-half),
        Some((Number::MINUS_ONE, Number::ZERO))
    );
    assert_eq!(
        exact_sin_cos(Number::ONE),
        Some((Number::ZERO, Number::MINUS_ONE))
    );
    assert_eq!(exact_sin_cos(Number::ratio(1, 3).unwrap()), None);
}
