//! The joint limits on URDF trees: at most `MAX_JOINTS` along a path from the base and
//! `MAX_TREE_JOINTS` in all, each refused at the first joint past it; Baxter's 19 joints (two
//! arms of seven with two fingers each, and the head) pass.

use dynamics_codegen::front::{load_urdf, Chain};
use dynamics_codegen::front::{FileError, Loaded};

const BAXTER: &str =
    include_str!("../../../../../../../robots/urdf/trees/baxter_free_fingers.urdf");

fn load(text: &str, tips: &[&str]) -> Result<Loaded, Vec<FileError>> {
    let chain = Chain {
        base: None,
        tip: None,
        tips,
    };
    load_urdf("r.urdf", text, chain, true)
}

/// Arms of the given numbers of revolute joints below `ground`, each on a fixed mount, one link
/// and its joint a line; returns the text and each moving joint's line.
fn arms(lengths: &[usize]) -> (String, Vec<usize>) {
    const INERTIAL: &str = r#"<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>"#;
    let mut text = String::from("<robot name=\"arms\">\n<link name=\"ground\"/>\n");
    let mut lines = Vec::new();
    for (arm, &length) in lengths.iter().enumerate() {
        text += &format!(
            "<link name=\"m{arm}\"/><joint name=\"mount{arm}\" type=\"fixed\">\
             <parent link=\"ground\"/><child link=\"m{arm}\"/></joint>\n"
        );
        for i in 0..length {
            let parent = match i {
                0 => format!("m{arm}"),
                _ => format!("a{arm}l{}", i - 1),
            };
            text += &format!(
                "<link name=\"a{arm}l{i}\">{INERTIAL}</link><joint name=\"a{arm}j{i}\" \
                 type=\"revolute\"><parent link=\"{parent}\"/><child link=\"a{arm}l{i}\"/>\
                 <axis xyz=\"0 0 1\"/></joint>\n"
            );
            lines.push(text.lines().count());
        }
    }
    (text + "</robot>\n", lines)
}

fn refused(text: &str, tips: &[&str]) -> (usize, String) {
    let e = load(text, tips).err().expect("an error").remove(0);
    (e.line.expect("a line"), e.message)
}

#[test]
fn baxter_s_nineteen_joints_load() {
    let robot = load(BAXTER, &[]).expect("Baxter").robot;
    assert_eq!(robot.dof(), 19);
    assert!(robot.is_tree());
    // Two arms of 16 and one of 4 pass too.
    load(&arms(&[16, 4, 16]).0, &[]).expect("36 joints");
}

#[test]
fn a_path_of_seventeen_joints_is_refused_at_its_seventeenth() {
    let (text, lines) = arms(&[3, 17, 2]);
    let (line, message) = refused(&text, &[]);
    // The second arm's 17th joint: the 20th moving joint of the file.
    assert_eq!(line, lines[3 + 16]);
    assert!(
        message.starts_with("joint 20 is the 17th joint on its path from the base; at most 16"),
        "{message}"
    );
    // That arm taken alone (`tips`) is a serial robot of 17 joints.
    let (line, message) = refused(&text, &["a1l16"]);
    assert_eq!(line, lines[3 + 16]);
    assert!(
        message.starts_with("17 joints; at most 16 are supported"),
        "{message}"
    );
}

#[test]
fn a_tree_of_sixty_five_joints_is_refused_at_its_sixty_fifth() {
    let (text, lines) = arms(&[13; 5]);
    let (line, message) = refused(&text, &[]);
    assert_eq!(line, lines[64]);
    assert!(
        message.starts_with("65 joints; at most 64 are supported in a tree (and 16 along"),
        "{message}"
    );
}
