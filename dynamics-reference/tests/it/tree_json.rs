//! The JSON form of trees: antecedents (absent: the joint before; `null`: the base), γ and b,
//! URDF-style joints, and the errors that name the joint and the field.

use dynamics_reference::{Convention, Robot};

fn robot(convention: &str, joints: &[&str]) -> Result<Robot, String> {
    let joints: Vec<String> = joints
        .iter()
        .map(|extra| format!(r#"{{"type": "revolute", {extra} "mass": 1.0, "com": [0, 0, 0.1], "inertia": [1, 1, 1, 0, 0, 0]}}"#))
        .collect();
    let json = format!(
        r#"{{"name": "t", "convention": "{convention}", "gravity": [0, 0, -9.81], "joints": [{}]}}"#,
        joints.join(", ")
    );
    Robot::from_json(&json).map_err(|e| e.to_string())
}

const ROW: &str = r#""theta": 0.1, "d": 0.2, "a": 0.3, "alpha": 0.4,"#;

#[test]
fn antecedents_default_to_the_joint_before() {
    let row_b = format!(r#"{ROW} "parent": null, "gamma": 0.5, "b": 0.6,"#);
    let row_c = format!(r#"{ROW} "parent": 0,"#);
    let tree = robot("modified", &[ROW, ROW, &row_b, &row_c, ROW]).expect("a tree");
    let parents: Vec<Option<usize>> = (0..5).map(|i| tree.antecedent(i)).collect();
    assert_eq!(parents, [None, Some(0), None, Some(0), Some(3)]);
    assert_eq!((tree.joints[2].gamma, tree.joints[2].b), (0.5, 0.6));
    assert_eq!((tree.joints[0].gamma, tree.joints[0].b), (0.0, 0.0));
    assert_eq!(tree.path(4), [0, 3, 4]);
    assert!(tree.moves(0, 4) && !tree.moves(1, 4) && !tree.moves(2, 3));
    // The JSON written back reads as the same robot.
    let again: Robot = serde_json::from_str(&serde_json::to_string(&tree).unwrap()).unwrap();
    assert_eq!(again, tree);
}

#[test]
fn urdf_style_joints_read_xyz_rpy_axis() {
    let tree = robot(
        "urdf",
        &[
            r#""xyz": [0, 0, 1], "rpy": [0, 0, 1.5707963267948966], "axis": [0, 1, 0],"#,
            r#""parent": null, "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "axis": [1, 0, 0],"#,
        ],
    )
    .expect("URDF style");
    assert_eq!(tree.convention, Convention::Urdf);
    assert_eq!(tree.antecedent(1), None);
    // Link 0 at q = 0: z up by 1, turned a quarter about z.
    let t = tree.frame(&[0.0, 0.0], 0);
    let want = [
        [0.0, -1.0, 0.0, 0.0],
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 1.0],
    ];
    for (r, row) in want.iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            assert!((t[(r, c)] - x).abs() < 1e-15, "({r}, {c}): {}", t[(r, c)]);
        }
    }
    let again: Robot = serde_json::from_str(&serde_json::to_string(&tree).unwrap()).unwrap();
    assert_eq!(again, tree);
}

#[test]
fn what_does_not_describe_a_tree_is_refused_with_the_joint_and_the_field() {
    let cases: [(&str, &[&str], &str); 7] = [
        (
            "standard",
            &[ROW, &format!(r#"{ROW} "parent": null,"#)],
            "joint 1: `parent` not allowed (a standard D-H table has no antecedent",
        ),
        (
            "standard",
            &[&format!(r#"{ROW} "gamma": 0.1,"#)],
            "joint 0: `gamma` not allowed",
        ),
        (
            "modified",
            &[ROW, &format!(r#"{ROW} "parent": 1,"#)],
            "joint 1: antecedent (`parent`) 1 does not come before it",
        ),
        (
            "modified",
            &[&format!(r#"{ROW} "axis": [0, 0, 1],"#)],
            "joint 0: `axis` not allowed",
        ),
        (
            "urdf",
            &[r#""theta": 0.1, "axis": [0, 0, 1],"#],
            "joint 0: `theta` not allowed (a URDF-style joint has no D-H values)",
        ),
        (
            "urdf",
            &[r#""xyz": [0, 0, 1],"#],
            "joint 0: missing field `axis`",
        ),
        (
            "urdf",
            &[r#""axis": [0, 0, 2],"#],
            "joint 0: `axis` [0.0, 0.0, 2.0] is not of unit length",
        ),
    ];
    for (convention, joints, want) in cases {
        let err = robot(convention, joints).expect_err(want);
        assert!(err.contains(want), "{err}\nshould contain: {want}");
    }
    let both =
        r#""rpy": [0, 0, 0], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "axis": [1, 0, 0],"#;
    assert!(robot("urdf", &[both])
        .unwrap_err()
        .contains("`rpy` or `rotation`, not both"));
}

#[test]
#[should_panic(
    expected = "joint 1: an antecedent other than the joint before, γ or b in a standard D-H table"
)]
fn a_tree_built_in_code_with_the_standard_convention_panics_with_the_reason() {
    let mut tree = robot("standard", &[ROW, ROW]).expect("a chain");
    tree.joints[1].parent = None;
    let _ = tree.mass_matrix(&[0.0, 0.0]);
}
