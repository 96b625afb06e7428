use dynamics_codegen::check::LinkParameter;
use dynamics_codegen::check::{friction, gear, geared_inertia};
use dynamics_codegen::front::parse_value;
use dynamics_codegen::model::Friction;

fn f(viscous: &str, coulomb: &str, smoothing: Option<&str>) -> Friction {
    Friction {
        viscous: parse_value(viscous).unwrap(),
        coulomb: parse_value(coulomb).unwrap(),
        offset: parse_value("-0.3").unwrap(),
        smoothing: smoothing.map(|s| parse_value(s).unwrap()),
    }
}

#[test]
fn physical_friction_passes() {
    assert!(friction(&f("0.1", "0", Some("0.01"))).is_empty());
    assert!(friction(&f("-fv", "-fc", Some("-eps"))).is_empty());
}

#[test]
fn negative_coefficients_and_smoothing_fail() {
    let p = friction(&f("-0.1", "1 - 3", Some("0")));
    let parameters: Vec<_> = p.iter().map(|p| p.parameter).collect();
    assert_eq!(
        parameters,
        [
            LinkParameter::FrictionViscous,
            LinkParameter::FrictionCoulomb,
            LinkParameter::FrictionSmoothing
        ]
    );
    assert!(p[0]
        .message
        .starts_with("the viscous friction coefficient is negative (-0.1)"));
    assert!(p[1]
        .message
        .starts_with("the Coulomb friction coefficient is negative (-2)"));
    assert!(p[2]
        .message
        .starts_with("the friction smoothing velocity is zero"));
    let p = friction(&f("0", "0", Some("-1e-3")));
    assert!(
        p[0].message.contains("is negative (-0.001)"),
        "{}",
        p[0].message
    );
}

#[test]
fn gears() {
    let v = |s: &str| parse_value(s).unwrap();
    assert!(gear(&v("1e-5"), &v("-100")).is_empty());
    let p = gear(&v("-1e-5"), &v("0"));
    assert_eq!(p[0].parameter, LinkParameter::RotorInertia);
    assert_eq!(p[1].parameter, LinkParameter::GearRatio);
    assert!(p[1].message.starts_with("the gear ratio is zero"));
    // N² I, exact: 100² × 3/10⁵ = 3/10.
    let i = geared_inertia(&v("0.00003"), &v("-100"));
    assert_eq!(i.exact(), v("0.3").exact());
}
