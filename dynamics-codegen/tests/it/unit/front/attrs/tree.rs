use dynamics_codegen::front::parse_str;
use dynamics_codegen::model::Robot;

const LINKS: &str = "link(mass = 1), link(mass = 1), link(mass = 1)";

fn robot(keys: &str) -> Robot {
    let text = format!(
        "#[derive(Dynamics)] #[dynamics(gravity = [0, 0, -9.81], {keys}, {LINKS})] struct Arm;"
    );
    parse_str(&text).unwrap_or_else(|e| panic!("{e}")).robot
}

fn error(keys: &str) -> String {
    let text =
        format!("#[derive(Dynamics)] #[dynamics(gravity = [0, 0, -9.81], {keys})] struct Arm;");
    parse_str(&text).err().expect("an error").to_string()
}

fn parents(robot: &Robot) -> Vec<Option<usize>> {
    (0..robot.dof()).map(|i| robot.parent(i)).collect()
}

/// `model::lower`'s hand-lowered tree: joint 3 at height 1/2 on joint 1, about y.
#[test]
fn joints_with_parents_by_name_and_number() {
    let tree = robot(
        r#"joints = [revolute(name = "palm"), revolute(parent = "palm", xyz = [1, 0, 0]),
           revolute(parent = 1, xyz = [0, 0, 0.5], axis = [0, 1, 0])]"#,
    );
    assert_eq!(parents(&tree), [None, Some(0), Some(0)]);
    let branch = tree.joints[2].branch.as_ref().unwrap();
    assert_eq!(branch.b.to_string(), "1/2");
    assert_eq!(tree.joints[2].alpha.to_string(), "-1/2 * pi");
    let chain = robot("joints = [revolute(parent = 0), revolute(parent = 1), revolute()]");
    assert!(chain.joints.iter().all(|j| j.branch.is_none()));
}

#[test]
fn modified_rows_with_an_antecedent_column() {
    let robot = robot(
        "convention = modified, dh = [[q, 0, 0.1, 0], [0, q, 0, 90 deg], \
         [q, 0, 0.3, 0, 1, -90 deg, 0.25]]",
    );
    assert_eq!(parents(&robot), [None, Some(0), Some(0)]);
    let branch = robot.joints[2].branch.as_ref().unwrap();
    let quarter = dynamics_codegen::symbolic::Number::ratio(-1, 2);
    assert_eq!(branch.gamma.pi_multiple(), quarter);
    assert_eq!(branch.b.to_string(), "1/4");
}

#[test]
fn mistakes_in_a_tree_are_errors() {
    let joints =
        |third: &str| format!("joints = [revolute(name = \"a\"), revolute(), {third}], {LINKS}");
    let cases = [
        (joints("revolute(parent = 4)"), "joint 3: parent 4: there is no joint 4 (3 are given; 0 is the base)"),
        (joints("revolute(parent = 3)"), "joint 3: parent joint 3: a joint cannot hang from itself (a cycle)"),
        (format!("joints = [revolute(parent = 2), revolute(), revolute()], {LINKS}"), "joint 1: parent joint 2 comes after it"),
        (joints("revolute(parent = \"b\")"), "joint 3: parent `b`: no joint has that name (the joints named are `a`)"),
        (joints("revolute(name = \"a\")"), "joint 1 is named `a` too"),
        (joints("revolute(parent = 1.5)"), "expected an earlier joint's number or name"),
        (format!("dh = [[q, 0, 0, 0], [q, 0, 0, 0, 1, 0, 0.5], [q, 0, 0, 0]], {LINKS}"), "a standard D-H table has no antecedent column"),
        (format!("convention = modified, dh = [[q, 0, 0, 0], [q, 0, 0, 0, 2, 0, 0], [q, 0, 0, 0]], {LINKS}"), "row 2: antecedent row 2: a row cannot hang from itself"),
        (format!("convention = modified, dh = [[q, 0, 0, 0], [q, 0, 0, 0, l, 0, 0], [q, 0, 0, 0]], {LINKS}"), "row 2: the antecedent is an earlier row's number"),
        (format!("convention = modified, dh = [[q, 0, 0, 0], [q, 0, 0, 0, 1, 0], [q, 0, 0, 0]], {LINKS}"), "takes 4 values, found 6"),
        ("file = \"robots/ur5.toml\", tips = [\"a\"]".into(), "`tips` names links of a URDF file"),
        ("urdf = \"../robots/urdf/ur5.urdf\", tip = \"tool0\", tips = [\"tool0\"]".into(), "`tips` cannot be combined with `tip`"),
        ("urdf = \"../robots/urdf/ur5.urdf\", tips = []".into(), "`tips` is empty"),
        ("urdf = \"../robots/urdf/ur5.urdf\", tips = [\"hand\"]".into(), "no link `hand` for `tips`"),
    ];
    for (keys, message) in cases {
        let e = error(&keys);
        assert!(e.contains(message), "{keys}\n{e}");
    }
}

#[test]
fn urdf_tips_in_the_derive() {
    let text = r#"#[derive(Dynamics)]
        #[dynamics(urdf = "../robots/urdf/trees/allegro_right_hand.urdf", check_inertia = false,
                   tips = ["link_3.0_tip", "link_15.0_tip"])]
        struct Hand;"#;
    let robot = parse_str(text).unwrap_or_else(|e| panic!("{e}")).robot;
    let roots = [
        None,
        Some(0),
        Some(1),
        Some(2),
        None,
        Some(4),
        Some(5),
        Some(6),
    ];
    assert_eq!(parents(&robot), roots);
}

/// `mimic = (joint = .., multiplier = .., offset = ..)` by name or number, and its mistakes
/// on their tokens; a mimic of a mimic and of the other kind from the model's check.
#[test]
fn mimic_joints_in_the_attribute() {
    let arm = robot(
        r#"joints = [revolute(name = "a"), revolute(mimic = (joint = "a", multiplier = -2)),
           revolute(mimic = (joint = 1, offset = 0.25))]"#,
    );
    // Written in the attribute as expressions (`-2` is `-(2)`): compared by value.
    let number = |v: &dynamics_codegen::model::Value| v.eval(&|_| None);
    type Rule = Option<(usize, Option<f64>, Option<f64>)>;
    let rules: Vec<Rule> = arm
        .joints
        .iter()
        .map(|j| {
            let m = j.mimic.as_ref()?;
            Some((m.joint, number(&m.multiplier), number(&m.offset)))
        })
        .collect();
    let second = Some((0, Some(-2.0), Some(0.0)));
    assert_eq!(rules, [None, second, Some((0, Some(1.0), Some(0.25)))]);
    let joints =
        |third: &str| format!("joints = [revolute(name = \"a\"), revolute(), {third}], {LINKS}");
    let cases = [
        (joints("revolute(mimic = (joint = 4))"), "joint 3: mimic joint 4: there is no joint 4 (joints are numbered 1 to 3)"),
        (joints("revolute(mimic = (joint = 0))"), "there is no joint 0"),
        (joints("revolute(mimic = (joint = 3))"), "joint 3: it cannot mimic itself"),
        (joints("revolute(mimic = (joint = \"b\"))"), "mimic joint `b`: no joint has that name"),
        (joints("revolute(mimic = (multiplier = 2))"), "`mimic` names no `joint`"),
        (joints("revolute(mimic = (joint = 1, gain = 2))"), "unknown mimic key `gain`"),
        (joints("revolute(mimic = (joint = 1.5))"), "expected the joint followed, by number or name"),
        (joints("revolute(mimic = 1)"), "expected `mimic = (joint = 2, multiplier = 1, offset = 0)`"),
        (joints("prismatic(mimic = (joint = 1))"), "joint 3: it follows joint 1, which is not of its kind"),
        (format!("joints = [revolute(), revolute(mimic = (joint = 3)), revolute(mimic = (joint = 1))], {LINKS}"), "joint 2: it follows joint 3, a mimic joint itself"),
    ];
    for (keys, message) in cases {
        let e = error(&keys);
        assert!(e.contains(message), "{keys}\n{e}");
    }
}
