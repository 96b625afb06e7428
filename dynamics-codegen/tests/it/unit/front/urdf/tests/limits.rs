//! `joint_limits`: the Panda's against Franka's published joint limits (the robot's datasheet:
//! position ranges, the 2.175 and 2.61 rad/s speeds, the 87 and 12 N·m torques), and a small file for the joints that
//! have no range or no `<limit>` and a value that is not a number.

use dynamics_codegen::front::{joint_limits, Chain, Limit};

const PANDA: &str = include_str!("../../../../../../../robots/urdf/panda.urdf");

fn limit(lower: f64, upper: f64, velocity: f64, effort: f64) -> Limit {
    Limit {
        lower: Some(lower),
        upper: Some(upper),
        velocity: Some(velocity),
        effort: Some(effort),
    }
}

#[test]
fn the_pandas_limits_are_franka_s() {
    let chain = Chain {
        base: Some("panda_link0"),
        tip: Some("panda_hand"),
        tips: &[],
    };
    let limits = joint_limits(PANDA, chain).expect("the Panda reads");
    let want = [
        limit(-2.8973, 2.8973, 2.175, 87.0),
        limit(-1.7628, 1.7628, 2.175, 87.0),
        limit(-2.8973, 2.8973, 2.175, 87.0),
        limit(-3.0718, -0.0698, 2.175, 87.0),
        limit(-2.8973, 2.8973, 2.61, 12.0),
        limit(-0.0175, 3.7525, 2.61, 12.0),
        limit(-2.8973, 2.8973, 2.61, 12.0),
    ];
    assert_eq!(limits, want);
}

const SMALL: &str = r#"<robot name="small">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="continuous"><parent link="base"/><child link="a"/>
    <limit lower="-1" upper="1" velocity="3" effort="5"/></joint>
  <joint name="fixed" type="fixed"><parent link="a"/><child link="b"/>
    <limit lower="-7" upper="7" velocity="7"/></joint>
  <joint name="j2" type="prismatic"><parent link="b"/><child link="c"/></joint>
</robot>"#;

#[test]
fn continuous_joints_have_no_range_and_fixed_joints_no_limits() {
    let limits = joint_limits(SMALL, Chain::default()).expect("reads");
    let continuous = Limit {
        velocity: Some(3.0),
        effort: Some(5.0),
        ..Limit::default()
    };
    assert_eq!(limits, [continuous, Limit::default()]);
}

#[test]
fn a_limit_that_is_not_a_number_is_an_error_where_it_is_written() {
    let bad = SMALL.replace("velocity=\"3\"", "velocity=\"fast\"");
    let errors = joint_limits(&bad, Chain::default()).unwrap_err();
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!((errors[0].line, errors[0].column), (Some(4), Some(43)));
    assert!(
        errors[0].message.contains("velocity=\"fast\""),
        "{}",
        errors[0]
    );
}
