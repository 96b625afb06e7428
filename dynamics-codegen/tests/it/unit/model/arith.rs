use dynamics_codegen::model::Value;

#[test]
fn numbers_fold_and_units_vanish() {
    let x = || Value::Field("x".into());
    let n = Value::from_f64;
    assert_eq!(n(0.1) + n(0.2), n(0.3));
    assert_eq!(n(0.0) + x(), x());
    assert_eq!(x() * n(1.0), x());
    assert_eq!(x() * n(0.0), Value::zero());
    assert_eq!(n(-1.0) * x(), -x());
    assert_eq!(-(-x()), x());
    assert_eq!(
        (x() + n(-0.5)).to_string(),
        "(x - 0.5)".replace("0.5", &n(0.5).to_string())
    );
}
