//! `--tool x,y,z,roll,pitch,yaw`: a tool frame on the hand from the command line, as a
//! description file's `tool`; refused beside a URDF (its tip link is the hand) and beside a file
//! that declares a tool.

use crate::runner::{dynamics, root};
use dynamics_test_support::Scratch;

/// The printed line of `name` (`px`, `J11`, …) of `dynamics inspect --kinematics` with `args`.
fn entry(args: &[&str], name: &str) -> String {
    let mut all = vec!["inspect", "--kinematics"];
    all.extend_from_slice(args);
    let out = dynamics(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let prefix = format!("  {name} = ");
    text.lines()
        .find_map(|l| l.strip_prefix(&prefix))
        .unwrap_or_else(|| panic!("no {name} in\n{text}"))
        .to_string()
}

/// The 3R arm's hand approach axis is `a = (S1, −C1, 0)` (z3 = z1 for α1 = 90°, α2 = α3 = 0),
/// so a tool 1/2 along it moves p by `(S1/2, −C1/2, 0)`; on the 2-link arm a tool 0.1 along
/// x2 lengthens the last link: `l2 → l2 + 0.1`, in p and in J's columns.
#[test]
fn a_tool_moves_the_hand_frame() {
    let arm = "robots/articulated_3r.toml";
    assert_eq!(entry(&[arm], "px"), "C1(a2 C2 + a3 C23)");
    let tool = ["--tool", "0,0,0.5,0,0,0"];
    assert_eq!(
        entry(&[arm, tool[0], tool[1]], "px"),
        "C1(a2 C2 + a3 C23) + 1/2 S1"
    );
    assert_eq!(
        entry(&[arm, tool[0], tool[1]], "py"),
        "S1(a2 C2 + a3 C23) - 1/2 C1"
    );
    assert_eq!(entry(&[arm, tool[0], tool[1]], "nx"), "C1 C23");
    let two = "robots/niku_example_6_4.toml";
    let tool = ["--tool", "0.1,0,0,0,0,0"];
    assert_eq!(
        entry(&[two, tool[0], tool[1]], "px"),
        "l1 C1 + (l2 + 0.1) C12"
    );
    assert_eq!(entry(&[two, tool[0], tool[1]], "J12"), "-(l2 + 0.1) S12");
}

/// A turned tool: yaw 180° about the hand's z turns n and o over, `n' = −n`, `o' = −o`.
#[test]
fn a_turned_tool_turns_the_hand_axes() {
    let two = "robots/niku_example_6_4.toml";
    let yaw = format!("0,0,0,0,0,{}", std::f64::consts::PI);
    let plain = entry(&[two], "nx");
    assert_eq!(plain, "C12");
    let turned = entry(&[two, "--tool", &yaw], "nx");
    assert_eq!(turned, "-C12", "nx with the tool turned");
    assert_eq!(entry(&[two, "--tool", &yaw], "oy"), "-C12");
}

#[test]
fn a_tool_is_refused_where_the_file_has_one() {
    let arm = std::fs::read_to_string(root().join("robots/articulated_3r.toml")).expect("read");
    let with_tool = arm.replace("gravity =", "tool = [0, 0, 1, 0, 0, 0]\ngravity =");
    let dir = Scratch::new("tool");
    let file = dir.write("arm.toml", &with_tool);
    let file = file.to_str().expect("UTF-8 path");
    let cases: [(&[&str], &str); 3] = [
        (
            &["robots/niku_example_6_4.toml", "--tool", "1,2"],
            "a tool takes 6 numbers",
        ),
        (
            &["robots/urdf/ur5.urdf", "--tool", "0,0,0,0,0,0"],
            "is its tip link; choose it with --tip",
        ),
        (
            &[file, "--tool", "0,0,0,0,0,0"],
            "declares a `tool` already",
        ),
    ];
    for (args, message) in cases {
        let mut all = vec!["stats"];
        all.extend_from_slice(args);
        let out = dynamics(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
    // Without --tool the file's own tool is taken.
    assert_eq!(entry(&[file], "px"), "C1(a2 C2 + a3 C23) + S1");
}
