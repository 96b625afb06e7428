use dynamics_codegen::symbolic::modular::{Fp, Points, P};
use dynamics_codegen::symbolic::Number;

#[test]
fn arithmetic() {
    let a = Fp::new(P - 1);
    assert_eq!(a + Fp::ONE, Fp::ZERO);
    assert_eq!(a * a, Fp::ONE);
    let x = Fp::new(123_456_789_012_345);
    assert_eq!(x * x.recip().unwrap(), Fp::ONE);
    assert_eq!(Fp::ZERO.recip(), None);
}

#[test]
fn exact_images() {
    let third = Fp::from_number(Number::ratio(1, 3).unwrap()).unwrap();
    assert_eq!(third * Fp::int(3), Fp::ONE);
    assert_eq!(Fp::from_f64(0.75) * Fp::int(4), Fp::int(3));
    assert_eq!(Fp::from_f64(-2.5) * Fp::int(2), Fp::int(-5));
    // 0.1 is not 1/10 as a float, but 0.1·2⁵⁵ is an integer.
    let tenth = Fp::from_f64(0.1);
    assert_ne!(tenth, Fp::int(10).recip().unwrap());
    assert_eq!(tenth * Fp(2).pow(55), Fp::int(3_602_879_701_896_397));
}

#[test]
fn circle_points() {
    let mut points = Points::new(7);
    for _ in 0..10 {
        let (s, c) = points.circle();
        assert_eq!(s * s + c * c, Fp::ONE);
    }
}

#[test]
fn small_rationals() {
    let x = Fp::int(-7) * Fp::int(12).recip().unwrap();
    assert_eq!(x.to_small_rational(1 << 30), Some((-7, 12)));
    assert_eq!(Fp::int(5).to_small_rational(1 << 30), Some((5, 1)));
    // 2⁵⁹ is 1/4 here (2⁶¹ ≡ 1); an arbitrary residue is no small rational.
    assert_eq!(Fp::new(1 << 59).to_small_rational(1 << 20), Some((1, 4)));
    assert_eq!(
        Fp::new(1_234_567_890_123_456_789).to_small_rational(1 << 20),
        None
    );
}
