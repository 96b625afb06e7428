//! The `dynamics` command on URDF files: `--base` and `--tip` choose the chain (`--tips` the
//! branches), errors name `file:line:col`, and the options are refused for other description
//! files.

use crate::runner::dynamics;
use std::process::Output;

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn a_urdf_chain_from_base_to_tip() {
    let out = dynamics(&[
        "stats",
        "robots/urdf/ur10.urdf",
        "--base",
        "base_link",
        "--tip",
        "tool0",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("ur10: 6 joints"), "{text}");
    let out = dynamics(&["stats", "robots/urdf/panda.urdf", "--tip", "panda_link8"]);
    assert!(
        String::from_utf8_lossy(&out.stdout).starts_with("panda: 7 joints"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn urdf_errors_name_the_file_line_and_column() {
    // Without a tip, every branch: the Panda's second finger follows the first (`<mimic>`),
    // no longer an error; a `<mimic>` naming itself is, at the element.
    let out = dynamics(&["stats", "robots/urdf/panda.urdf"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let file = "dynamics-runtime/tests/ui/trees/mimic_itself.urdf";
    let out = dynamics(&["inspect", file]);
    assert_eq!(out.status.code(), Some(1));
    let want = format!(
        "{file}:25:5: joint `elbow`'s `<mimic joint=\"elbow\">`: a joint cannot follow itself"
    );
    assert!(stderr(&out).contains(&want), "{}", stderr(&out));
    let file = "dynamics-runtime/tests/ui/urdf/negative_mass.urdf";
    let out = dynamics(&["inspect", file]);
    assert_eq!(out.status.code(), Some(1));
    let want = format!("dynamics: {file}:15:20: link `fore`: the mass is negative (-1.5)");
    assert!(stderr(&out).starts_with(&want), "{}", stderr(&out));
    let out = dynamics(&["inspect", "robots/urdf/ur5.urdf", "--tip", "hand"]);
    assert!(
        stderr(&out).contains("no link `hand` for `tip`"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn base_and_tip_are_for_urdf_files() {
    let out = dynamics(&["inspect", "robots/ur5.toml", "--tip", "tool0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--base, --tip and --tips name links of a URDF file"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn tips_choose_the_branches() {
    // One tip: the serial path to it, as `--tip` gives (the fingers below cut off).
    let stats = |choice: &str| {
        let out = dynamics(&["stats", "robots/urdf/panda.urdf", choice, "panda_link8"]);
        assert!(out.status.success(), "{}", stderr(&out));
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let tips = stats("--tips");
    assert!(tips.starts_with("panda: 7 joints"), "{tips}");
    // The counts, without the lines that give times.
    let counts = |text: &str| {
        let lines = text.lines().filter(|line| !line.contains(" ms"));
        lines.collect::<Vec<_>>().join("\n")
    };
    assert_eq!(counts(&tips), counts(&stats("--tip")));
    let tree = "robots/urdf/trees/allegro_right_hand.urdf";
    let out = dynamics(&["inspect", tree, "--tips", "link_3.0_tip,hand"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("allegro_right_hand.urdf:6:1: no link `hand` for `tips`"),
        "{}",
        stderr(&out)
    );
    let out = dynamics(&[
        "inspect",
        tree,
        "--tip",
        "link_3.0_tip",
        "--tips",
        "link_7.0_tip",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("cannot be used with"),
        "{}",
        stderr(&out)
    );
    let out = dynamics(&["inspect", "robots/ur5.toml", "--tips", "tool0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--base, --tip and --tips name links of a URDF file"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_tree_prints_its_branches() {
    // The Panda with both fingers free: finger 2 (joint 9) hangs from the hand on link 7, beside
    // finger 1 (joint 8), so D89 is zero by the structure and left out.
    let out = dynamics(&["inspect", "robots/urdf/trees/panda_free_fingers.urdf"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8_lossy(&out.stdout);
    let tree =
        "a tree (Khalil-Kleinfinger's antecedents): joints 1-8 from the base; joint 9 from joint 7";
    assert!(text.contains(tree), "{text}");
    let zeros = "zero, as their joints are on different branches (left out below): D89\n";
    assert!(text.contains(zeros), "{text}");
    assert!(!text.contains("\n  D89 ="), "{text}");
    assert!(text.contains("\n  D79 = D97 ="), "{text}");
    let out = dynamics(&["stats", "robots/urdf/trees/panda_free_fingers.urdf"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("panda: 9 joints in 2 branches,"), "{text}");
    let chain = dynamics(&["inspect", "robots/urdf/panda.urdf", "--tip", "panda_link8"]);
    assert!(!String::from_utf8_lossy(&chain.stdout).contains("a tree"));
}

#[test]
fn published_inertias_pass_with_no_check_inertia() {
    // The Allegro hand's URDF has links whose principal moments break the triangle
    // inequality: refused, with the option named, then read as given.
    let hand = "robots/urdf/trees/allegro_right_hand.urdf";
    let out = dynamics(&["stats", hand]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("`--no-check-inertia` to the command"),
        "{}",
        stderr(&out)
    );
    let out = dynamics(&["stats", hand, "--no-check-inertia"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.starts_with("allegro_hand_right: 16 joints in 4 branches,"),
        "{text}"
    );
    let out = dynamics(&["emit", hand, "--tips", "link_3.0_tip", "--no-check-inertia"]);
    let text = String::from_utf8_lossy(&out.stdout);
    let command =
        format!("Generated by `dynamics emit {hand} --tips link_3.0_tip --no-check-inertia`");
    assert!(text.contains(&command), "{}", stderr(&out));
}
