use dynamics_codegen::front::angle::unitless_angle;
use dynamics_codegen::front::parse_spanned;

/// The value of the first offending term of `text`, if any.
fn flagged(text: &str) -> Option<String> {
    let s = parse_spanned(text).expect("value");
    unitless_angle(&s.unitless, false).map(|(t, _)| format!("{}", t.value.to_f64()))
}

#[test]
fn plain_numbers_above_two_pi_are_flagged() {
    assert_eq!(flagged("90").as_deref(), Some("90"));
    assert_eq!(flagged("-90").as_deref(), Some("-90"));
    assert_eq!(flagged("q + 90").as_deref(), Some("90"));
    assert_eq!(flagged("q - 7").as_deref(), Some("7"));
    assert_eq!(flagged("pi/2 + 45 * 2").as_deref(), Some("90"));
    assert_eq!(flagged("(45 + 45)").as_deref(), Some("90"));
    // 6.3 > 2π = 6.2832, 6.28 < 2π.
    assert_eq!(flagged("6.3").as_deref(), Some("6.3"));
    assert_eq!(flagged("6.28"), None);
}

#[test]
fn units_pi_and_fields_are_taken_as_written() {
    for text in [
        "90 deg",
        "-90 deg",
        "q + 90 deg",
        "90 rad",
        "-90 rad",
        "q - 100 rad",
        "pi/2 + 3",
        "2 * pi",
        "3 * pi / 2",
        "pi / 180 * 90",
        "q + offset",
        "100 * offset",
        "(q + 90) rad",
        "1.5707963267948966",
        "-3.14159",
    ] {
        assert_eq!(flagged(text), None, "{text}");
    }
}

#[test]
fn message_suggests_degrees() {
    assert_eq!(
        dynamics_codegen::front::angle::message(dynamics_codegen::symbolic::Number::int(90), false),
        "an angle of 90 without a unit is 90 radians (5157°): write `90 deg`, or `90 rad` \
         if you mean radians"
    );
    let m = dynamics_codegen::front::angle::message(
        dynamics_codegen::symbolic::Number::ratio(-63, 10).unwrap(),
        true,
    );
    assert!(
        m.starts_with("an angle of -6.3 without a unit is -6.3 radians (-361°)"),
        "{m}"
    );
    assert!(m.contains("`\"-6.3 deg\"`, or `\"-6.3 rad\"`"), "{m}");
}
