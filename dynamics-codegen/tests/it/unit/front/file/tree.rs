use dynamics_codegen::front::{from_json, from_toml};
use dynamics_codegen::model::Robot;

const LINK: &str = "mass = 1\ninertia = [1, 1, 1, 0, 0, 0]\n";

fn toml_joints(joints: &[&str]) -> String {
    let mut text = String::from("gravity = [0, 0, -9.81]\n");
    for j in joints {
        text += &format!("[[joints]]\n{j}\n{LINK}");
    }
    text
}

fn parents(robot: &Robot) -> Vec<Option<usize>> {
    (0..robot.dof()).map(|i| robot.parent(i)).collect()
}

/// The tree of `model::lower`'s hand-lowered test: joint 3 hangs from joint 1 at height
/// 1/2, about y: b = 1/2, α = −90°.
#[test]
fn frames_with_parents_by_name_and_number() {
    let toml = toml_joints(&[
        "name = \"palm\"\ntype = \"revolute\"\naxis = [0, 0, 1]",
        "type = \"revolute\"\nparent = \"palm\"\norigin = { xyz = [1, 0, 0] }",
        "type = \"revolute\"\nparent = 1\norigin = { xyz = [0, 0, 0.5] }\naxis = [0, 1, 0]",
    ]);
    let robot = from_toml(&toml, "x").unwrap();
    assert_eq!(parents(&robot), [None, Some(0), Some(0)]);
    let third = &robot.joints[2];
    let branch = third.branch.as_ref().unwrap();
    assert_eq!(
        (branch.gamma.to_string(), branch.b.to_string()),
        ("0".into(), "1/2".into())
    );
    assert_eq!(third.alpha.to_string(), "-1/2 * pi");
    // Parents that make a chain leave it a chain.
    let chain = toml_joints(&[
        "type = \"revolute\"\nparent = 0\naxis = [0, 0, 1]",
        "type = \"revolute\"\nparent = 1\norigin = { xyz = [1, 0, 0] }",
    ]);
    let chain = from_toml(&chain, "x").unwrap();
    assert!(chain.joints.iter().all(|j| j.branch.is_none()));
}

#[test]
fn modified_rows_with_an_antecedent_column_in_toml_and_json() {
    let toml = format!(
        "convention = \"modified\"\n{}",
        toml_joints(&[
            "type = \"revolute\"\na = 0.1",
            "type = \"prismatic\"\nalpha = \"90 deg\"",
            "type = \"revolute\"\nparent = 1\ngamma = \"-90 deg\"\nb = 0.25\na = 0.3",
        ])
    );
    let json = r#"{"convention": "modified", "gravity": [0, 0, -9.81], "joints": [
        {"type": "revolute", "a": 0.1, "mass": 1, "inertia": [1, 1, 1, 0, 0, 0]},
        {"type": "prismatic", "alpha": "90 deg", "mass": 1, "inertia": [1, 1, 1, 0, 0, 0]},
        {"type": "revolute", "parent": 1, "gamma": "-90 deg", "b": 0.25, "a": 0.3,
         "mass": 1, "inertia": [1, 1, 1, 0, 0, 0]}]}"#;
    for robot in [
        from_toml(&toml, "x").unwrap(),
        from_json(json, "x").unwrap(),
    ] {
        assert_eq!(parents(&robot), [None, Some(0), Some(0)]);
        let branch = robot.joints[2].branch.as_ref().unwrap();
        let quarter = dynamics_codegen::symbolic::Number::ratio(-1, 2);
        assert_eq!(branch.gamma.pi_multiple(), quarter);
        assert_eq!(branch.b.to_string(), "1/4");
        assert_eq!(robot.joints[2].a.to_string(), "3/10");
    }
}

/// Each mistake at its key's line (`at`, the key's line written).
#[test]
fn mistakes_in_a_tree_are_placed() {
    let frame = "type = \"revolute\"\naxis = [0, 0, 1]";
    let row = "type = \"revolute\"";
    let named = "name = \"a\"\ntype = \"revolute\"";
    let cases: [(String, &str, &str); 9] = [
        (toml_joints(&[frame, "type = \"revolute\"\nparent = 3", frame]), "parent = 3", "joint 2: parent joint 3 comes after it"),
        (toml_joints(&[frame, "type = \"revolute\"\nparent = 2"]), "parent = 2", "a joint cannot hang from itself (a cycle)"),
        (toml_joints(&[frame, "type = \"revolute\"\nparent = 7"]), "parent = 7", "there is no joint 7 (2 are given; 0 is the base)"),
        (toml_joints(&[named, "type = \"revolute\"\nparent = \"b\""]), "parent = \"b\"", "parent `b`: no joint has that name (the joints named are `a`)"),
        (toml_joints(&[row, named, named]), "name = \"a\"\ntype = \"revolute\"\nmass = 1\ninertia = [1, 1, 1, 0, 0, 0]\n[[joints]]\nname", "joint 3: joint 2 is named `a` too"),
        (toml_joints(&[row, "type = \"revolute\"\nparent = 0"]), "parent = 0", "a standard D-H table has no antecedent column"),
        (toml_joints(&[row, "type = \"revolute\"\ngamma = 0.5"]), "gamma", "`gamma` is Khalil-Kleinfinger's, of the modified convention"),
        (toml_joints(&[frame, "type = \"revolute\"\nparent = 1\nb = 0.5"]), "b = 0.5", "`b` is a D-H parameter of a tree (Khalil-Kleinfinger); a joint given by `origin` and `axis` has it derived"),
        (toml_joints(&[frame, "type = \"revolute\"\nparent = -1"]), "parent = -1", "parent -1: name an earlier joint"),
    ];
    for (text, at, message) in cases {
        let e = from_toml(&text, "x").expect_err(&text);
        // The line of the last line of `at` (a repeated key is the later one).
        let offset = text.rfind(at).unwrap() + at.rfind('\n').map_or(0, |k| k + 1);
        let line = text[..offset].matches('\n').count() + 1;
        assert_eq!(e.line, Some(line), "{e}\n{text}");
        assert!(e.message.contains(message), "{e}\n{text}");
    }
}

/// `mimic = { joint = .., multiplier = .., offset = .. }` by number or name, either side;
/// each mistake at its `mimic` key, a mimic of a mimic at the joint (the model's check).
#[test]
fn mimic_joints_and_their_mistakes() {
    let frame = "type = \"revolute\"\naxis = [0, 0, 1]";
    let toml = toml_joints(&[
        "type = \"revolute\"\nmimic = { joint = \"b\", multiplier = -0.5, offset = 0.1 }",
        "name = \"b\"\ntype = \"revolute\"\norigin = { xyz = [1, 0, 0] }",
        "type = \"revolute\"\nmimic = { joint = 2 }\norigin = { xyz = [0, 1, 0] }",
    ]);
    let robot = from_toml(&toml, "x").unwrap();
    let rules: Vec<Option<(usize, String, String)>> = robot
        .joints
        .iter()
        .map(|j| {
            let m = j.mimic.as_ref()?;
            Some((m.joint, m.multiplier.to_string(), m.offset.to_string()))
        })
        .collect();
    let first = Some((1, "-1/2".to_string(), "1/10".to_string()));
    assert_eq!(rules, [first, None, Some((1, "1".into(), "0".into()))]);
    assert_eq!(robot.coordinates(), [1]);
    let cases: [(String, &str, &str); 4] = [
        (
            toml_joints(&[frame, "type = \"revolute\"\nmimic = { joint = 5 }"]),
            "mimic",
            "joint 2: mimic joint 5: there is no joint 5 (the file has 2",
        ),
        (
            toml_joints(&[frame, "type = \"revolute\"\nmimic = { joint = 2 }"]),
            "mimic",
            "joint 2: a joint cannot mimic itself",
        ),
        (
            toml_joints(&[frame, "type = \"revolute\"\nmimic = { joint = \"z\" }"]),
            "mimic",
            "mimic joint `z`: no joint has that name",
        ),
        (
            toml_joints(&[
                frame,
                "type = \"revolute\"\nmimic = { joint = 1, gain = 2 }",
            ]),
            "gain",
            "unknown field `gain`",
        ),
    ];
    for (text, at, message) in cases {
        let e = from_toml(&text, "x").expect_err(&text);
        let line = text[..text.rfind(at).unwrap()].matches('\n').count() + 1;
        assert_eq!(e.line, Some(line), "{e}\n{text}");
        assert!(e.message.contains(message), "{e}\n{text}");
    }
}
