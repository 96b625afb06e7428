use dynamics_codegen::front::parse_value;
use dynamics_codegen::model::Value;
use dynamics_codegen::symbolic::Number;

#[test]
fn literals_stay_exact() {
    assert_eq!(
        parse_value("0.4318").unwrap(),
        Value::Num(Number::ratio(4318, 10000).unwrap())
    );
    assert_eq!(
        parse_value("90 deg").unwrap().pi_multiple(),
        Number::ratio(1, 2)
    );
    assert_eq!(
        parse_value("-pi/2").unwrap().pi_multiple(),
        Number::ratio(-1, 2)
    );
    assert_eq!(
        Value::from_f64(std::f64::consts::FRAC_PI_2).pi_multiple(),
        Number::ratio(1, 2)
    );
    assert_eq!(
        Value::from_f64(-std::f64::consts::FRAC_PI_2).pi_multiple(),
        Number::ratio(-1, 2)
    );
    assert_eq!(Value::from_f64(1.2).pi_multiple(), None);
}

#[test]
fn expressions_over_fields() {
    let v = parse_value("m2 * l2^2 / 12").unwrap();
    let x = v.eval(&|f| match f {
        "m2" => Some(3.0),
        "l2" => Some(2.0),
        _ => None,
    });
    assert_eq!(x, Some(1.0));
    assert_eq!(
        parse_value("q + 90 deg")
            .unwrap()
            .joint_offset()
            .unwrap()
            .pi_multiple(),
        Number::ratio(1, 2)
    );
    assert!(parse_value("2 * q").unwrap().joint_offset().is_none());
    assert!(parse_value("3 +").is_err());
}

#[test]
fn keywords_name_fields_and_unrawable_names_are_refused() {
    let field = |text: &str| match parse_value(text) {
        Ok(Value::Field(name)) => name,
        other => panic!("{text}: {other:?}"),
    };
    assert_eq!(field("type"), "type");
    assert_eq!(field("r#type"), "type");
    assert_eq!(field("self.fn"), "fn");
    assert_eq!(field("self.r#gen"), "gen");
    assert_eq!(field("r#pi"), "pi");
    assert_eq!(parse_value("pi").unwrap(), Value::Pi);
    for text in [
        "self",
        "Self",
        "super",
        "crate",
        "_",
        "self.Self",
        "2 * Self",
    ] {
        let e = parse_value(text).unwrap_err();
        assert!(e.contains("cannot name a parameter"), "{text}: {e}");
    }
}

#[test]
fn suffixes_are_refused() {
    for (text, says) in [
        ("2m", "no suffix"),
        ("2.5f64", "without the suffix `f64`"),
        ("1f32", "without the suffix `f32`"),
        ("90deg", "`90 deg`"),
        ("q + 1rad", "`1 rad`"),
    ] {
        let e = parse_value(text).unwrap_err();
        assert!(e.contains(says), "{text}: {e}");
    }
    // The units themselves are fine: `rad` keeps the number as it is.
    assert_eq!(parse_value("2 rad").unwrap(), Value::Num(Number::int(2)));
}
