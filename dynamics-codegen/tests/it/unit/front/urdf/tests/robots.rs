//! The URDF reader on the real robots of `robots/urdf/` and on small hand-made files. Expected
//! masses are summed here from the file's own numbers, read with a plain XML walk; merged
//! inertias are checked against a hand computation.

use dynamics_codegen::front::{load_urdf, Chain};
use dynamics_codegen::front::{FileError, Loaded};
use dynamics_codegen::model::{JointKind, Robot, Value};
use dynamics_codegen::symbolic::Number;

const UR5: &str = include_str!("../../../../../../../robots/urdf/ur5.urdf");
const UR10: &str = include_str!("../../../../../../../robots/urdf/ur10.urdf");
const PANDA: &str = include_str!("../../../../../../../robots/urdf/panda.urdf");
const Z1: &str = include_str!("../../../../../../../robots/urdf/z1.urdf");
const SO101: &str = include_str!("../../../../../../../robots/urdf/so101.urdf");

fn load(text: &str, base: Option<&str>, tip: Option<&str>) -> Result<Loaded, Vec<FileError>> {
    load_urdf(
        "robot.urdf",
        text,
        Chain {
            base,
            tip,
            tips: &[],
        },
        true,
    )
}

fn robot(text: &str, tip: Option<&str>) -> Robot {
    match load(text, None, tip) {
        Ok(loaded) => loaded.robot,
        Err(e) => panic!("{e:?}"),
    }
}

fn num(v: &Value) -> f64 {
    v.eval(&|_| None).expect("a number")
}

fn exact(text: &str) -> Value {
    Value::num(Number::parse_decimal(text).expect("a decimal"))
}

/// The mass `<link name>` declares, read straight from the XML: 0 without `<inertial>`.
fn mass_in_file(text: &str, link: &str) -> Value {
    let doc = roxmltree::Document::parse(text).expect("xml");
    let node = doc
        .descendants()
        .find(|n| n.has_tag_name("link") && n.attribute("name") == Some(link))
        .unwrap_or_else(|| panic!("no link {link}"));
    node.descendants()
        .find(|n| n.has_tag_name("mass"))
        .map_or_else(Value::zero, |m| exact(m.attribute("value").expect("value")))
}

fn masses_in_file(text: &str, links: &[&str]) -> Value {
    links
        .iter()
        .fold(Value::zero(), |acc, l| acc + mass_in_file(text, l))
}

fn axes(robot: &Robot) -> Vec<[f64; 3]> {
    robot
        .joints
        .iter()
        .map(|j| j.frame.as_ref().expect("a frame").axis.each_ref().map(num))
        .collect()
}

fn check_chain(
    robot: &Robot,
    kinds: usize,
    axes_expected: &[[f64; 3]],
    bodies: &[&[&str]],
    text: &str,
) {
    assert_eq!(robot.dof(), kinds);
    assert!(robot.joints.iter().all(|j| j.kind == JointKind::Revolute));
    assert_eq!(axes(robot), axes_expected);
    for (joint, links) in robot.joints.iter().zip(bodies) {
        assert_eq!(joint.link.mass, masses_in_file(text, links), "{links:?}");
    }
}

const Z: [f64; 3] = [0.0, 0.0, 1.0];
const Y: [f64; 3] = [0.0, 1.0, 0.0];
const X: [f64; 3] = [1.0, 0.0, 0.0];

#[test]
fn ur5_and_ur10_are_six_revolute_joints() {
    let axes = [Z, Y, Y, Y, Z, Y];
    // The default chain ends at wrist_3_link; ee_link and tool0 are fixed to it.
    let ur5 = robot(UR5, None);
    let bodies: [&[&str]; 6] = [
        &["shoulder_link"],
        &["upper_arm_link"],
        &["forearm_link"],
        &["wrist_1_link"],
        &["wrist_2_link"],
        &["wrist_3_link", "ee_link", "tool0"],
    ];
    check_chain(&ur5, 6, &axes, &bodies, UR5);
    assert_eq!(ur5.name, "ur5");
    let ur10 = robot(UR10, Some("tool0"));
    check_chain(&ur10, 6, &axes, &bodies, UR10);
    // shoulder_lift_joint: `<origin rpy="0.0 1.57079632679 0.0" xyz="0.0 0.220941 0.0"/>`.
    let origin = &ur10.joints[1].frame.as_ref().unwrap().origin;
    assert_eq!(origin.xyz, ["0.0", "0.220941", "0.0"].map(exact));
    assert_eq!(origin.rpy, ["0.0", "1.57079632679", "0.0"].map(exact));
    // The gravity of a URDF robot, by default.
    assert_eq!(ur10.gravity, ["0", "0", "-9.81"].map(exact));
    // UR files declare zero damping and friction: no friction.
    assert!(ur10.joints.iter().all(|j| j.link.friction.is_none()));
}

#[test]
fn panda_to_its_flange() {
    let panda = robot(PANDA, Some("panda_link8"));
    let bodies: Vec<Vec<String>> = (1..=7).map(|i| vec![format!("panda_link{i}")]).collect();
    let mut bodies: Vec<Vec<&str>> = bodies
        .iter()
        .map(|b| b.iter().map(String::as_str).collect())
        .collect();
    // panda_joint8 and panda_hand_joint are fixed: link 8 and the hand are part of link 7; the
    // fingers below the hand move, and are cut off.
    bodies[6].extend(["panda_link8", "panda_hand"]);
    let bodies: Vec<&[&str]> = bodies.iter().map(Vec::as_slice).collect();
    check_chain(&panda, 7, &[Z; 7], &bodies, PANDA);
    // `<dynamics damping="0.003" friction="0.0"/>`: viscous friction only.
    let friction = panda.joints[0].link.friction.as_ref().expect("friction");
    assert_eq!(
        (friction.viscous.clone(), friction.coulomb.clone()),
        (exact("0.003"), Value::zero())
    );
}

#[test]
fn z1_with_its_gripper_and_friction() {
    let z1 = robot(Z1, None);
    let bodies: [&[&str]; 7] = [
        &["link01"],
        &["link02"],
        &["link03"],
        &["link04"],
        &["link05"],
        &["link06", "gripperStator"],
        &["gripperMover"],
    ];
    check_chain(&z1, 7, &[Z, Y, Y, Y, Z, X, Y], &bodies, Z1);
    // jointGripper's placement: gripperStator's fixed offset (0.051, 0, 0), then its own
    // origin (0.049, 0, 0).
    let origin = &z1.joints[6].frame.as_ref().unwrap().origin;
    assert_eq!(origin.xyz, ["0.1", "0", "0"].map(exact));
    let friction = z1.joints[1].link.friction.as_ref().expect("friction");
    assert_eq!(
        (friction.viscous.clone(), friction.coulomb.clone()),
        (exact("2"), exact("2"))
    );
}

#[test]
fn so101_with_its_jaw() {
    let so101 = robot(SO101, None);
    let bodies: [&[&str]; 6] = [
        &["shoulder_link"],
        &["upper_arm_link"],
        &["lower_arm_link"],
        &["wrist_link"],
        &["gripper_link", "gripper_frame_link"],
        &["moving_jaw_so101_v1_link"],
    ];
    check_chain(&so101, 6, &[Z; 6], &bodies, SO101);
}
