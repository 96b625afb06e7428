use dynamics_codegen::identifiers::*;

#[test]
fn keywords_are_raw_fields_and_the_unrawable_are_refused() {
    assert_eq!(rust_field("type").unwrap().to_string(), "r#type");
    assert_eq!(rust_field("gen").unwrap().to_string(), "r#gen");
    assert_eq!(rust_field("int").unwrap().to_string(), "int");
    assert_eq!(rust_field("ñ").unwrap().to_string(), "ñ");
    for name in ["self", "Self", "super", "crate", "_"] {
        assert!(rust_field(name)
            .unwrap_err()
            .contains("cannot name a parameter"));
    }
    assert!(rust_field("1m").is_err());
    assert!(rust_field("r#type").is_err());
}

#[test]
fn struct_names_avoid_self_and_digits() {
    assert_eq!(rust_type("two_link"), "TwoLink");
    assert_eq!(rust_type("self"), "RobotSelf");
    assert_eq!(rust_type("Self"), "RobotSelf");
    assert_eq!(rust_type("type"), "Type");
    assert_eq!(rust_type("1arm"), "Robot1arm");
    assert_eq!(rust_type("ñ"), "Robot");
    assert_eq!(rust_type("-/-"), "Robot");
}

#[test]
fn prefixes_are_plain_c_names() {
    assert_eq!(c_prefix("UR5e"), "ur5e");
    assert_eq!(c_prefix("arm-a"), "arm_a");
    assert_eq!(c_prefix("--arm--a--"), "arm_a");
    assert_eq!(c_prefix("_Arm"), "arm");
    assert_eq!(c_prefix("1arm"), "robot_1arm");
    assert_eq!(c_prefix("ñ"), "robot");
    for robot in ["UR5e", "arm-a", "__x", "1", "ñ", "a__b", "-_-"] {
        assert_eq!(c_prefix_problem(&c_prefix(robot)), None, "{robot}");
    }
    for bad in ["", "_arm", "1arm", "arm_", "a__b", "arm-a", "ñ"] {
        assert!(c_prefix_problem(bad).is_some(), "{bad}");
    }
}

#[test]
fn c_parameter_locals_are_distinct_and_plain() {
    assert_eq!(c_parameter(0, "m1"), "p_m1");
    assert_eq!(c_parameter(1, "int"), "p_int");
    assert_eq!(c_parameter(2, "_m"), "p_2");
    assert_eq!(c_parameter(3, "m__2"), "p_3");
    assert_eq!(c_parameter(4, "θ"), "p_4");
}

#[test]
fn control_characters_are_escaped() {
    assert_eq!(one_line("arm\nfn x() {}"), "arm\\nfn x() {}");
    assert_eq!(one_line("a\0b"), "a\\0b");
    assert_eq!(one_line("θ"), "θ");
}
