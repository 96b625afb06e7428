use dynamics_codegen::poly::Poly;

macro_rules! same {
    ($($a:literal => $b:literal),* $(,)?) => {$(
        assert_eq!(Poly::parse($a).unwrap(), Poly::parse($b).unwrap(), "{} != {}", $a, $b);
    )*};
}

#[test]
fn canonical_forms() {
    same! {
        "S1^2 + C1^2" => "1",
        "C12" => "C1*C2 - S1*S2",
        "S12" => "S1*C2 + C1*S2",
        "(m + m)/2" => "m",
        "1/3*m*l^2 + m*l^2/6" => "m*l^2/2",
        "x - x" => "0",
        "q2*qd2 - qdd1" => "-qdd1 + qd2*q2",
    }
    assert_eq!(
        Poly::parse("2*m*l^2*C2 - 1/2*g").unwrap().to_string(),
        "-1/2*g + 2*l^2*m*C2"
    );
}

#[test]
fn what_is_not_a_polynomial() {
    for text in ["pi * m", "q * m", "m / l", "m / 0", "2 *"] {
        assert!(Poly::parse(text).is_err(), "{text}");
    }
}
