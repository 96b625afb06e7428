//! `urdf = ".."` in the derive: the chain read, `gravity` replacing the default, and the keys
//! that cannot go with it.

use dynamics_codegen::front::parse_str;
use dynamics_codegen::model::Value;

// Unit tests run in the crate's directory: the robots are one level up.
#[test]
fn the_derive_reads_a_urdf_chain() {
    let input = parse_str(
        r#"#[derive(Dynamics)]
        #[dynamics(urdf = "../robots/urdf/ur10.urdf", base = "base_link", tip = "tool0", gravity = [0, 0, -g])]
        struct Ur10 { g: f64 }"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(input.robot.dof(), 6);
    assert_eq!(input.robot.name, "ur10");
    assert!(input.tracked_file.is_some_and(|f| f.ends_with("ur10.urdf")));
    assert_eq!(
        input.robot.gravity[2],
        Value::Neg(Box::new(Value::Field("g".into())))
    );
}

#[test]
fn keys_that_do_not_go_with_urdf() {
    let error = |attrs: &str| {
        let text = format!("#[derive(Dynamics)] #[dynamics({attrs})] struct Arm;");
        parse_str(&text).err().expect("an error").to_string()
    };
    let e = error(r#"urdf = "../robots/urdf/ur5.urdf", convention = modified"#);
    assert!(
        e.contains("`convention` cannot be combined with `urdf`"),
        "{e}"
    );
    let e = error(r#"file = "../robots/ur5.toml", base = "base_link""#);
    assert!(e.contains("`base` names a link of a URDF file"), "{e}");
}
