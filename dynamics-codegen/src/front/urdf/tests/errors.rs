//! Bad input: each mistake an error at the line and column of the element or attribute that
//! makes it.

use super::super::{load_urdf, Chain};
use crate::front::FileError;

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
    match load_urdf("r.urdf", text, Chain { base: None, tip }, true) {
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
    let cases: [Case; 10] = [
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
            two_links(&joint("revolute", "<mimic joint=\"j0\"/>"), INERTIAL),
            None,
            (4, 69),
            "has `<mimic>`",
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
fn a_moving_branch_before_the_tip_is_refused() {
    let branch = format!(
        "{}<link name=\"c\"/><joint name=\"side\" type=\"prismatic\"><parent link=\"a\"/><child link=\"c\"/></joint>",
        joint("revolute", "")
    );
    let text = two_links(&branch, INERTIAL);
    // Without a tip the robot branches at `a`; with tip `b`, the joint `side` is a branch.
    let (line, _, message) = first(&text, None);
    assert_eq!(line, 3);
    assert!(
        message.contains("branches at link `a` (joints `j1` and `side`)"),
        "{message}"
    );
    let (line, column, message) = first(&text, Some("b"));
    assert_eq!((line, column), (4, 93));
    assert!(
        message.contains("`<joint name=\"side\">` branches off the chain at link `a`"),
        "{message}"
    );
    // With tip `a`, both are below the tip and cut off.
    let loaded = load_urdf(
        "r.urdf",
        &text,
        Chain {
            base: None,
            tip: Some("a"),
        },
        true,
    )
    .expect("loads");
    assert_eq!(loaded.robot.dof(), 1);
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
