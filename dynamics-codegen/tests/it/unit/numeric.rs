use dynamics_codegen::front;
use dynamics_codegen::numeric::Numeric;

#[test]
fn fields_are_required() {
    let robot = front::from_toml(
        "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = \"m\"\n",
        "x",
    )
    .unwrap();
    assert!(Numeric::new(&robot, &[]).is_err());
    let n = Numeric::new(&robot, &[("m", 2.0)]).unwrap();
    assert_eq!(n.gravity_torques(&[0.3]), vec![0.0]);
}
