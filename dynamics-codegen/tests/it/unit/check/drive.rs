use dynamics_codegen::check::drive;
use dynamics_codegen::check::LinkParameter;
use dynamics_codegen::front::parse_value;
use dynamics_codegen::model::{Spring, Value};

fn spring(k: &str, rest: &str) -> Spring {
    Spring {
        stiffness: parse_value(k).unwrap(),
        rest: parse_value(rest).unwrap(),
    }
}

#[test]
fn physical_drives_pass() {
    let i = parse_value("0.02").unwrap();
    assert!(drive(&i, Some(&spring("5", "-pi/2"))).is_empty());
    assert!(drive(&Value::zero(), Some(&spring("0", "0"))).is_empty());
    // Fields are read at run time: a negative one is the user's to give.
    assert!(drive(&parse_value("-i").unwrap(), Some(&spring("-k", "r"))).is_empty());
}

#[test]
fn negative_and_infinite_values_fail() {
    let p = drive(&parse_value("-0.1").unwrap(), Some(&spring("2 - 7", "0")));
    assert_eq!(p.len(), 2);
    assert_eq!(p[0].parameter, LinkParameter::ActuatorInertia);
    assert!(p[0]
        .message
        .starts_with("the actuator inertia is negative (-0.1)"));
    assert_eq!(p[1].parameter, LinkParameter::SpringStiffness);
    assert!(p[1]
        .message
        .starts_with("the spring stiffness is negative (-5)"));
    let infinite = Value::from_f64(f64::INFINITY);
    let p = drive(
        &Value::zero(),
        Some(&Spring {
            stiffness: Value::zero(),
            rest: infinite,
        }),
    );
    assert_eq!(p[0].parameter, LinkParameter::SpringRest);
    assert!(p[0].message.contains("not a finite number"));
}
