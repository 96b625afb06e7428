//! Bad input: each mistake an error at the line and column of the element or attribute that
//! makes it.

use dynamics_codegen::front::urdf::xml::Lines;
use dynamics_codegen::front::FileError;
use dynamics_codegen::front::{load_urdf, Chain};

/// Two links `a` (line 3) and `b` (line 6) joined by `joint` (line 4), with `b`'s inertial.
fn two_links(joint: &str, inertial: &str) -> String {
    format!(
        "<robot name=\"r\">\n\
         <link name=\"ground\"/>\n\
         <link name=\"a\"/>\n\
         {joint}\n\
         <joint name=\"j0\" type=\"revolute\"><parent link=\"ground\"/><child link=\"a\"/></joint>\n\
         <link name=\"b\">{inertial}</link>\n\
         </robot>\n"
    )
}

const INERTIAL: &str = r#"<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>"#;

fn errors(text: &str, tip: Option<&str>) -> Vec<FileError> {
    match load_urdf(
        "r.urdf",
        text,
        Chain {
            base: None,
            tip,
            tips: &[],
        },
        true,
    ) {
        Ok(_) => panic!("no error for\n{text}"),
        Err(e) => e,
    }
}

fn first(text: &str, tip: Option<&str>) -> (usize, usize, String) {
    let e = errors(text, tip).remove(0);
    (
        e.line.expect("a line"),
        e.column.expect("a column"),
        e.message,
    )
}

fn joint(kind: &str, inner: &str) -> String {
    format!(
        "<joint name=\"j1\" type=\"{kind}\"><parent link=\"a\"/><child link=\"b\"/>{inner}</joint>"
    )
}

/// `<mimic>` read: the joint followed, the multiplier and offset; one coordinate fewer.
#[test]
fn a_mimic_joint_follows_its_joint() {
    let mimic = "<mimic joint=\"j0\" multiplier=\"-2\" offset=\"0.5\"/>";
    let text = two_links(&joint("revolute", mimic), INERTIAL);
    let robot = load_urdf("r.urdf", &text, Chain::default(), true)
        .expect("loads")
        .robot;
    let rule = robot.joints[1].mimic.as_ref().expect("a mimic joint");
    let said = (
        rule.joint,
        rule.multiplier.to_string(),
        rule.offset.to_string(),
    );
    assert_eq!(said, (0, "-2".into(), "1/2".into()));
    assert_eq!(robot.coordinates(), [0]);
    // A mimic joint that is cut off with its branch is no problem: one joint, no rule.
    let cut = load_urdf(
        "r.urdf",
        &text,
        Chain {
            tip: Some("a"),
            ..Chain::default()
        },
        true,
    );
    assert!(cut.expect("loads").robot.joints[0].mimic.is_none());
    // Following a joint that is cut off is: the rule would read a joint the robot lacks.
    let text = two_links(&joint("revolute", ""), INERTIAL).replace(
        "<child link=\"a\"/></joint>",
        "<child link=\"a\"/><mimic joint=\"j1\"/></joint>",
    );
    let e = errors(&text, Some("a")).remove(0);
    assert!(
        e.message
            .contains("`j1` is not a moving joint of the robot"),
        "{}",
        e.message
    );
}

#[test]
fn a_good_file_loads() {
    let text = two_links(&joint("revolute", ""), INERTIAL);
    let loaded = load_urdf("r.urdf", &text, Chain::default(), true).expect("loads");
    assert_eq!(loaded.robot.dof(), 2);
    assert_eq!(loaded.sources.joints[1]["type"], (4, 1));
}

/// A file, its tip, where the error is and what it says.
type Case<'a> = (String, Option<&'a str>, (usize, usize), &'a str);

#[test]
fn each_mistake_at_its_place() {
    let cases: [Case; 9] = [
        (
            "<robot><link name=\"a\">\n</robot>".into(),
            None,
            (2, 1),
            "malformed XML",
        ),
        (
            two_links(&joint("floating", ""), INERTIAL),
            None,
            (4, 1),
            "a floating joint moves",
        ),
        (
            two_links(&joint("planar", ""), INERTIAL),
            None,
            (4, 1),
            "a planar joint moves",
        ),
        (
            two_links(&joint("revolute", "<axis xyz=\"0 0 0\"/>"), INERTIAL),
            None,
            (4, 80),
            "is zero",
        ),
        (
            two_links(&joint("prismatic", "<axis xyz=\"0 1 1\"/>"), INERTIAL),
            None,
            (4, 81),
            "has length 1.414",
        ),
        (
            two_links(&joint("revolute", "<dynamics damping=\"-0.5\"/>"), INERTIAL),
            None,
            (4, 88),
            "`<dynamics damping=\"-0.5\">` is negative",
        ),
        (
            two_links(
                &joint("revolute", ""),
                &INERTIAL.replace("value=\"1\"", "value=\"-2\""),
            ),
            None,
            (6, 39),
            "link `b`: the mass is negative",
        ),
        (
            two_links(
                &joint("revolute", ""),
                &INERTIAL.replace("izz=\"1\"", "izz=\"3\""),
            ),
            None,
            (6, 57),
            "link `b`: the principal moments of inertia 1, 1, 3 break the triangle inequality",
        ),
        (
            two_links(&joint("revolute", ""), INERTIAL),
            Some("hand"),
            (1, 1),
            "no link `hand` for `tip`",
        ),
    ];
    for (text, tip, at, message) in cases {
        let (line, column, got) = first(&text, tip);
        assert!(got.contains(message), "{got}\nwanted: {message}");
        assert_eq!((line, column), at, "{got}");
    }
}

#[test]
fn a_moving_branch_before_the_tip_is_refused_and_without_a_tip_makes_a_tree() {
    let branch = format!(
        "{}<link name=\"c\"/><joint name=\"side\" type=\"prismatic\"><parent link=\"a\"/><child link=\"c\"/></joint>",
        joint("revolute", "")
    );
    let text = two_links(&branch, INERTIAL);
    // With tip `b`, the joint `side` is a branch.
    let (line, column, message) = first(&text, Some("b"));
    assert_eq!((line, column), (4, 93));
    assert!(
        message.contains("`<joint name=\"side\">` branches off the chain at link `a`"),
        "{message}"
    );
    let load = |tip, tips| {
        let chain = Chain {
            base: None,
            tip,
            tips,
        };
        load_urdf("r.urdf", &text, chain, true)
            .expect("loads")
            .robot
    };
    // With tip `a`, both are below the tip and cut off.
    assert_eq!(load(Some("a"), &[]).dof(), 1);
    // Without a tip, a tree: `j0` (written last) from the ground, `j1` and `side` from `a`, in
    // the file's order; so with both tips.
    for tips in [&[][..], &["b", "c"]] {
        let tree = load(None, tips);
        let parents: Vec<_> = (0..3).map(|i| tree.parent(i)).collect();
        assert_eq!(parents, [None, Some(0), Some(0)], "{tips:?}");
        assert!(tree.is_tree());
    }
    // The branch to `c` alone: a chain, `j1` cut off.
    let chain = load(None, &["c"]);
    assert_eq!(chain.dof(), 2);
    assert!(chain.joints.iter().all(|j| j.branch.is_none()));
    assert_eq!(
        chain.joints[1].kind,
        dynamics_codegen::model::JointKind::Prismatic
    );
}

#[test]
fn tips_unknown_or_not_below_the_base_or_beside_a_tip_are_refused() {
    let text = two_links(&joint("revolute", ""), INERTIAL);
    let refused = |base, tip, tips| {
        let chain = Chain { base, tip, tips };
        let e = load_urdf("r.urdf", &text, chain, true)
            .err()
            .expect("an error");
        (e[0].line, e[0].column, e[0].message.clone())
    };
    let (line, _, message) = refused(None, None, &["b", "hand"]);
    assert_eq!(line, Some(1));
    assert!(
        message.starts_with("no link `hand` for `tips`: the links are"),
        "{message}"
    );
    let (line, column, message) = refused(Some("b"), None, &["a"]);
    assert_eq!((line, column), (Some(3), Some(1)));
    assert_eq!(
        message,
        "`tips`: the link `a` is not below the base link `b`"
    );
    let (line, _, message) = refused(None, Some("b"), &["b"]);
    assert_eq!(line, Some(1));
    assert!(
        message.starts_with("`tip` and `tips` are both given"),
        "{message}"
    );
}

#[test]
fn a_tip_above_the_base_is_refused() {
    let text = two_links(&joint("revolute", ""), INERTIAL);
    let e = load_urdf(
        "r.urdf",
        &text,
        Chain {
            base: Some("b"),
            tip: Some("a"),
            tips: &[],
        },
        true,
    )
    .err()
    .expect("an error");
    assert!(
        e[0].message
            .contains("the tip link `a` is not below the base link `b`"),
        "{:?}",
        e[0]
    );
}

#[test]
fn a_xacro_file_is_sent_to_xacro() {
    let xacro = "<?xml version=\"1.0\"?>\n\
                 <robot name=\"arm\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n  \
                 <xacro:property name=\"l\" value=\"0.5\"/>\n  \
                 <xacro:macro name=\"arm\" params=\"n\"><link name=\"${n}\"/></xacro:macro>\n  \
                 <xacro:arm n=\"base\"/>\n\
                 </robot>\n";
    let (line, column, message) = first(xacro, None);
    assert_eq!((line, column), (3, 3), "{message}");
    assert!(
        message.starts_with("`<xacro:property>`: this is a xacro file, not a URDF")
            && message.contains("`xacro robot.urdf.xacro > robot.urdf`"),
        "{message}"
    );
    // Without the namespace declared, the XML itself is wrong; the advice is the same.
    let undeclared = "<robot name=\"arm\">\n<xacro:include filename=\"arm.xacro\"/>\n</robot>";
    let (line, _, message) = first(undeclared, None);
    assert_eq!(line, 2, "{message}");
    assert!(
        message.starts_with("a `xacro:` element: this is a xacro file"),
        "{message}"
    );
    // An expanded file may keep the declaration (`robots/urdf/ur5.urdf` does): it loads.
    let expanded = two_links(&joint("revolute", ""), INERTIAL).replace(
        "<robot name=\"r\">",
        "<robot name=\"r\" xmlns:xacro=\"http://wiki.ros.org/xacro\">",
    );
    assert!(load_urdf("r.urdf", &expanded, Chain::default(), true).is_ok());
}

/// Positions found by the line index are roxmltree's, at every character of a text with
/// multi-byte characters across the index's checkpoints, `\r\n` and tabs.
#[test]
fn positions_are_roxmltrees() {
    let long = "é€😀a".repeat(40);
    let text = format!(
        "<robot>\r\n\t<link name=\"ü\"/>\n<!-- {long} --><link name=\"{long}\"/>\n\n</robot>"
    );
    let doc = roxmltree::Document::parse(&text).expect("XML");
    let lines = Lines::new(&text);
    for (offset, _) in text.char_indices().chain([(text.len(), ' ')]) {
        let pos = doc.text_pos_at(offset);
        let expected = (pos.row as usize, pos.col as usize);
        assert_eq!(
            lines.at(text.as_bytes(), offset),
            expected,
            "at byte {offset}"
        );
    }
}

/// A robot of `n` links `l0`, `l1`, .. below `ground`, each joint of type `kind`.
fn long_chain(n: usize, kind: &str) -> String {
    let mut text = String::from("<robot name=\"long\">\n<link name=\"ground\"/>\n");
    for i in 0..n {
        let parent = if i == 0 {
            "ground".to_string()
        } else {
            format!("l{}", i - 1)
        };
        text += &format!("<link name=\"l{i}\"/><joint name=\"j{i}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"l{i}\"/></joint>\n");
    }
    text + "</robot>\n"
}

/// Reading a file of many links was quadratic: each position was counted from the start of the
/// text, each link walked up to the root, each joint searched below for a moving one, and every
/// moving joint built and lowered before the count was checked. 28,000 links took more than the
/// fuzzer's bound of 10 s; 20,000 now take a fraction of a second.
#[test]
fn long_chains_load_in_linear_time() {
    let start = std::time::Instant::now();
    let fixed = long_chain(20_000, "fixed");
    let (line, column, message) = first(&fixed, None);
    assert_eq!((line, column), (1, 1), "{message}");
    assert!(message.starts_with("no joint moves"), "{message}");
    // Past 16 moving joints the chain is refused before it is built: at the 17th joint.
    let moving = long_chain(20_000, "revolute");
    let (line, column, message) = first(&moving, None);
    assert_eq!((line, column), (19, 19), "{message}");
    assert!(message.starts_with("20000 joints; at most 16"), "{message}");
    let elapsed = start.elapsed();
    assert!(elapsed < std::time::Duration::from_secs(5), "{elapsed:?}");
}

#[test]
fn a_loop_is_named_at_a_link_on_it() {
    // `a` → `b` → `c` → `b`: `b` and `c` are on the loop; `a` is not.
    let text = "<robot>\n<link name=\"a\"/>\n<link name=\"b\"/>\n<link name=\"c\"/>\n\
                <joint name=\"ab\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n\
                <joint name=\"bc\" type=\"fixed\"><parent link=\"b\"/><child link=\"c\"/></joint>\n\
                <joint name=\"cb\" type=\"fixed\"><parent link=\"c\"/><child link=\"b\"/></joint>\n\
                </robot>";
    let all = errors(text, None);
    let looped = all
        .iter()
        .find(|e| e.message.contains("own ancestor"))
        .expect("a loop");
    assert_eq!(
        (looped.line, looped.column),
        (Some(3), Some(1)),
        "{looped:?}"
    );
}

/// roxmltree counts at most 255 spaces around an attribute's `=`: past them, the value was
/// placed in the spaces.
#[test]
fn a_value_after_many_spaces_at_its_place() {
    let spaces = " ".repeat(300);
    let axis = format!("<axis xyz{spaces}=\n {spaces}\"0 0 0\"/>");
    let text = two_links(&joint("revolute", &axis), INERTIAL);
    let (line, column, message) = first(&text, None);
    assert_eq!((line, column), (5, 303), "{message}");
    assert!(message.contains("is zero"), "{message}");
}

/// Each mistake of a `<mimic>` at the element (or its attribute).
#[test]
fn mimic_mistakes_at_the_element() {
    let cases: [Case; 5] = [
        (
            two_links(&joint("revolute", "<mimic joint=\"j1\"/>"), INERTIAL),
            None,
            (4, 69),
            "joint `j1`'s `<mimic joint=\"j1\">`: a joint cannot follow itself",
        ),
        (
            two_links(&joint("revolute", "<mimic joint=\"jx\"/>"), INERTIAL),
            None,
            (4, 69),
            "the file has no joint `jx`",
        ),
        (
            two_links(&joint("prismatic", "<mimic joint=\"j0\"/>"), INERTIAL),
            None,
            (4, 70),
            "`j1` and `j0` are not of the same kind (revolute or prismatic)",
        ),
        (
            two_links(&joint("revolute", "<mimic multiplier=\"2\"/>"), INERTIAL),
            None,
            (4, 69),
            "`<mimic>` has no `joint` attribute",
        ),
        (
            two_links(
                &joint("revolute", "<mimic joint=\"j0\" offset=\"x\"/>"),
                INERTIAL,
            ),
            None,
            (4, 95),
            "offset",
        ),
    ];
    for (text, tip, at, message) in cases {
        let (line, column, said) = first(&text, tip);
        assert_eq!((line, column), at, "{said}");
        assert!(said.contains(message), "{said}");
    }
}
