//! Fixed links merged and inertial axes turned, against hand computations.

use dynamics_codegen::front::{load_urdf, Chain};
use dynamics_codegen::model::{Robot, Value};
use dynamics_codegen::symbolic::Number;

/// A one-joint robot whose moving link `a` carries `extra` (links and joints).
fn arm(a_inertial: &str, extra: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<robot name="arm">
  <link name="ground"/>
  <joint name="hinge" type="revolute">
    <parent link="ground"/><child link="a"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
  </joint>
  <link name="a">{a_inertial}</link>
  {extra}
</robot>"#
    )
}

fn robot(text: &str) -> Robot {
    match load_urdf("arm.urdf", text, Chain::default(), true) {
        Ok(loaded) => loaded.robot,
        Err(e) => panic!("{e:?}"),
    }
}

fn ratio(n: i128, d: i128) -> Value {
    Value::num(Number::ratio(n, d).expect("a ratio"))
}

#[test]
fn a_fixed_link_merges_by_the_parallel_axis_theorem() {
    // Link a: 2 kg at its origin, diag(1, 2, 3). Link b, fixed at (1, 0, 0) turned a quarter
    // turn about z: 1 kg, centre of mass (0, 0.5, 0) in b, diag(0.1, 0.2, 0.3) in b's axes.
    // By hand: b's centre of mass in a is Rz(90°)(0, 0.5, 0) + (1, 0, 0) = (0.5, 0, 0) and its
    // inertia diag(0.2, 0.1, 0.3) (x and y swap). Total 3 kg at c = (1/6, 0, 0); offsets
    // d_a = −1/6, d_b = 1/3 along x add m d² = 2/36 + 1/9 = 1/6 to Iyy and Izz:
    // I = diag(1.2, 2.1 + 1/6, 3.3 + 1/6) = diag(6/5, 34/15, 52/15).
    let a = r#"<inertial><mass value="2"/><inertia ixx="1" iyy="2" izz="3" ixy="0" ixz="0" iyz="0"/></inertial>"#;
    let b = r#"<joint name="bolt" type="fixed"><parent link="a"/><child link="b"/>
        <origin xyz="1 0 0" rpy="0 0 1.5708"/></joint>
      <link name="b"><inertial><origin xyz="0 0.5 0"/><mass value="1"/>
        <inertia ixx="0.1" iyy="0.2" izz="0.3" ixy="0" ixz="0" iyz="0"/></inertial></link>"#;
    let joint = &robot(&arm(a, b)).joints[0];
    assert_eq!(joint.link.mass, ratio(3, 1));
    assert_eq!(joint.link.com, [ratio(1, 6), Value::zero(), Value::zero()]);
    assert_eq!(
        joint.link.inertia,
        [
            ratio(6, 5),
            ratio(34, 15),
            ratio(52, 15),
            Value::zero(),
            Value::zero(),
            Value::zero()
        ]
    );
}

#[test]
fn inertial_axes_turn_to_the_link_s() {
    // diag(1, 2, 3) in axes turned by roll 0.3 about x: in the link's axes
    // Iyy = 2c² + 3s², Izz = 2s² + 3c², Iyz = (2 − 3) s c, with (s, c) = sin, cos 0.3.
    let a = r#"<inertial><origin xyz="0.1 0.2 0.3" rpy="0.3 0 0"/><mass value="2"/>
        <inertia ixx="1" iyy="2" izz="3" ixy="0" ixz="0" iyz="0"/></inertial>"#;
    let joint = &robot(&arm(a, "")).joints[0];
    let (s, c) = 0.3f64.sin_cos();
    let want = [
        1.0,
        2.0 * c * c + 3.0 * s * s,
        2.0 * s * s + 3.0 * c * c,
        0.0,
        0.0,
        -s * c,
    ];
    for (got, want) in joint.link.inertia.iter().zip(want) {
        let got = got.eval(&|_| None).expect("a number");
        assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    }
    let exact = |t| Value::num(Number::parse_decimal(t).expect("decimal"));
    assert_eq!(joint.link.com, ["0.1", "0.2", "0.3"].map(exact));
    // The joint's placement is its origin as written.
    let origin = &joint.frame.as_ref().expect("a frame").origin;
    assert_eq!(origin.xyz, ["0", "0", "0.5"].map(exact));
}

#[test]
fn fixed_joints_before_a_moving_one_fold_into_its_placement() {
    // ground → (fixed, turned a quarter turn about z, at (1, 0, 0)) → plate → hinge at
    // (0, 2, 0): in ground's frame the hinge sits at (1, 0, 0) + Rz(90°)(0, 2, 0) = (−1, 0, 0)
    // with yaw π/2.
    let text = r#"<robot name="r">
      <link name="ground"/><link name="plate"/>
      <joint name="mount" type="fixed"><parent link="ground"/><child link="plate"/>
        <origin xyz="1 0 0" rpy="0 0 1.5707963267948966"/></joint>
      <joint name="hinge" type="continuous"><parent link="plate"/><child link="a"/>
        <origin xyz="0 2 0"/><axis xyz="1 0 0"/></joint>
      <link name="a"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
    </robot>"#;
    let joint = &robot(text).joints[0];
    let origin = &joint.frame.as_ref().expect("a frame").origin;
    let xyz = origin
        .xyz
        .each_ref()
        .map(|v| v.eval(&|_| None).expect("number"));
    assert_eq!(xyz, [-1.0, 0.0, 0.0]);
    let rpy = origin
        .rpy
        .each_ref()
        .map(|v| v.eval(&|_| None).expect("number"));
    assert_eq!(rpy, [0.0, 0.0, std::f64::consts::FRAC_PI_2]);
}
