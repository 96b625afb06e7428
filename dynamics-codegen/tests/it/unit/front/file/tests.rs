use dynamics_codegen::front::{from_json, from_toml, load};
use dynamics_codegen::model::{Convention, JointKind};
use dynamics_codegen::symbolic::Number;

#[test]
fn json_and_toml_agree() {
    let json = r#"{"name": "arm", "convention": "standard", "gravity": [0, -9.81, 0],
      "joints": [{"type": "revolute", "theta": 0.0, "d": 0.0, "a": 0.7, "alpha": 1.5707963267948966,
                  "mass": 2.0, "com": [-0.35, 0, 0], "inertia": [0, 0.1, 0.1, 0, 0, 0]}]}"#;
    let toml = r#"
        name = "arm"
        gravity = [0, -9.81, 0]
        [[joints]]
        type = "revolute"
        a = 0.7
        alpha = "90 deg"
        mass = 2
        com = [-0.35, 0, 0]
        inertia = [0, 0.1, 0.1, 0, 0, 0]
    "#;
    let a = from_json(json, "x").unwrap();
    let b = from_toml(toml, "x").unwrap();
    assert_eq!(a.convention, Convention::Standard);
    assert_eq!(a.joints[0].kind, JointKind::Revolute);
    assert_eq!(
        a.joints[0].alpha.pi_multiple(),
        b.joints[0].alpha.pi_multiple()
    );
    assert_eq!(a.joints[0].link.mass, b.joints[0].link.mass);
    assert_eq!(a.joints[0].link.com, b.joints[0].link.com);
}

/// As in frames and URDFs, 1.5708 and −3.14159 are quarter turns; 1.5709 is not.
#[test]
fn dh_angles_near_quarter_turns_snap() {
    let alpha = |written: &str| {
        let toml = format!(
            "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"prismatic\"\ntheta = -3.14159\n\
             alpha = {written}\nmass = 1\n"
        );
        let robot = from_toml(&toml, "x").unwrap();
        assert_eq!(robot.joints[0].theta.pi_multiple(), Some(Number::int(-1)));
        robot.joints[0].alpha.pi_multiple()
    };
    assert_eq!(alpha("1.5708"), Some(Number::ratio(1, 2).unwrap()));
    assert_eq!(alpha("1.5709"), None);
}

#[test]
fn errors_have_positions() {
    let e = from_json(
        "{\n \"gravity\": [0, 0, -9.81],\n \"joints\": [{\"type\": \"revolut\"}]}",
        "x",
    )
    .unwrap_err();
    assert!(e.message.contains("revolut"), "{e}");
    let e = from_json("{\n \"gravity\": [0, 0, -9.81],\n \"jionts\": []}", "x").unwrap_err();
    assert_eq!(e.line, Some(3));
    assert!(e.message.contains("jionts"));
    let e = from_toml("gravity = [0, 0]\njoints = []", "x").unwrap_err();
    assert_eq!(e.line, Some(1));
}

#[test]
fn values_have_positions_for_later_checks() {
    let json = "{\"gravity\": [0, 0, -9.81], \"name\": \"a{[\\\"\",\n \"joints\": [\n  {\"type\": \"revolute\", \"mass\": 1},\n  {\"type\": \"revolute\",\n   \"mass\": 2, \"inertia\": [1, 2, 3, 0, 0, 0]}]}";
    let loaded = load("a.json", json).expect("json");
    let positions = &loaded.sources.joints;
    assert_eq!(positions.len(), 2);
    assert_eq!(positions[0]["mass"], (3, 32));
    assert_eq!(positions[1]["mass"], (5, 12));
    assert_eq!(positions[1]["inertia"], (5, 26));
    let toml = "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\n[[joints]]\ntype = \"prismatic\"\nmass = 2\ninertia = [1, 2, 3, 0, 0, 0]\n";
    let loaded = load("a.toml", toml).expect("toml");
    assert_eq!(loaded.sources.joints[0]["mass"], (4, 8));
    assert_eq!(loaded.sources.joints[1]["inertia"], (9, 11));
}

#[test]
fn unitless_angles_are_refused_at_their_position() {
    let toml = "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\nalpha = 90\n";
    let e = load("a.toml", toml).err().expect("an error");
    assert_eq!((e.line, e.column), (Some(5), Some(9)));
    assert!(
        e.message
            .starts_with("joint 1: an angle of 90 without a unit"),
        "{e}"
    );
    assert!(e.message.contains("`\"90 deg\"`"), "{e}");
    let json = "{\"gravity\": [0, 0, -9.81], \"joints\": [\n {\"type\": \"prismatic\", \"mass\": 1,\n  \"theta\": \"pi/2 + 180\"}]}";
    let e = load("a.json", json).err().expect("an error");
    assert_eq!((e.line, e.column), (Some(3), Some(12)));
    assert!(e.message.contains("an angle of 180 without"), "{e}");
    // Radians said so, degrees, and numbers within 2π pass.
    for alpha in ["\"90 rad\"", "\"90 deg\"", "-3.14159", "6", "\"q\""] {
        let text = format!(
            "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\nalpha = {alpha}\n"
        );
        let ok = load("a.toml", &text);
        assert_eq!(ok.is_ok(), alpha != "\"q\"", "{alpha}");
    }
}
