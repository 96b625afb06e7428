use dynamics_codegen::check::link::{link, short, LinkParameter};
use dynamics_codegen::front::parse_value;
use dynamics_codegen::model::Value;

fn values(text: [&str; 6]) -> [Value; 6] {
    text.map(|t| parse_value(t).expect("value"))
}

#[test]
fn physical_links_pass() {
    let zero = Value::zero();
    // A thin rod (0, I, I) is the edge of the triangle inequality and passes.
    let rod = values(["0", "0.08", "0.08", "0", "0", "0"]);
    assert!(link(&parse_value("2").unwrap(), &rod, true).is_empty());
    // Products of inertia that keep the tensor positive definite.
    let tilted = values(["0.1", "0.12", "0.15", "0.01", "-0.005", "0.002"]);
    assert!(link(&zero, &tilted, true).is_empty());
    // Fields are unknown at compile time and pass.
    let fields = values(["m * l^2", "0", "0", "0", "0", "0"]);
    assert!(link(&parse_value("m").unwrap(), &fields, true).is_empty());
}

#[test]
fn unphysical_links_fail_unless_unchecked() {
    let mass = parse_value("4.8").unwrap();
    // PUMA 560 link 3: 0.0125 + 0.066 < 0.086.
    let puma3 = values(["0.066", "0.086", "0.0125", "0", "0", "0"]);
    let p = link(&mass, &puma3, true);
    assert_eq!(p.len(), 1);
    assert_eq!(p[0].parameter, LinkParameter::Inertia);
    assert!(
        p[0].message.contains("0.0125 + 0.066 < 0.086"),
        "{}",
        p[0].message
    );
    assert!(link(&mass, &puma3, false).is_empty());
    // |Ixy| > √(Ixx Iyy): an eigenvalue of [[1, 2], [2, 1]] is −1.
    let indefinite = values(["1", "1", "1", "2", "0", "0"]);
    let p = link(&mass, &indefinite, true);
    assert!(
        p[0].message.contains("positive semi-definite"),
        "{}",
        p[0].message
    );
    assert!(p[0].message.contains("-1,"), "{}", p[0].message);
    let p = link(&parse_value("-0.5").unwrap(), &Default::default(), true);
    assert_eq!(p[0].parameter, LinkParameter::Mass);
    assert!(p[0].message.contains("negative (-0.5)"), "{}", p[0].message);
}

#[test]
fn short_numbers() {
    assert_eq!(short(0.0125), "0.0125");
    assert_eq!(short(0.086_000_000_000_01), "0.086");
    assert_eq!(short(-1.0), "-1");
    assert_eq!(short(12345.6), "12346");
    assert_eq!(short(4e-5), "0.00004");
}
