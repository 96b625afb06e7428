//! The base regressor's springs.

use dynamics_codegen::{load, JointColumns, Source};
use dynamics_identification::Regressor;

/// Joint 3 follows joint 2 (`q3 = −0.5 q2 + 0.2`), both with springs: their torques on
/// coordinate 2 are `2 (q2 − 0.3) + (−0.5) · 4 (−0.5 q2 + 0.2 − 0.1)`
/// `= 3 q2 − 0.8`, one spring of stiffness 3 at rest 0.8 / 3.
#[test]
fn a_mimic_joints_spring_is_carried_onto_its_coordinate() {
    let text = r#"
name = "sprung"
gravity = [0, 0, -9.81]

[[joints]]
type = "revolute"
mass = 1

[[joints]]
name = "driver"
type = "revolute"
a = 0.5
mass = 1
spring_stiffness = 2
spring_rest = 0.3

[[joints]]
type = "revolute"
a = 0.4
mass = 1
spring_stiffness = 4
spring_rest = 0.1
mimic = { joint = "driver", multiplier = -0.5, offset = 0.2 }
"#;
    let source = Source {
        path: "sprung.toml",
        text: Some(text),
        ..Source::default()
    };
    let robot = load(&source).expect("loads").robot;
    let joints = vec![JointColumns::default(); robot.joints.len()];
    let regressor = Regressor::new(&robot, joints, Vec::new()).expect("a regressor");
    let springs = regressor.springs();
    assert_eq!(springs.len(), 2);
    assert_eq!(springs[0], None);
    let (k, rest) = springs[1].expect("a spring");
    assert!(
        (k - 3.0).abs() < 1e-15 && (rest - 0.8 / 3.0).abs() < 1e-15,
        "{k} {rest}"
    );
}
