use dynamics_codegen::check::Problem;
use dynamics_codegen::check::{joint_count, MAX_JOINTS, MAX_TREE_JOINTS};

/// `arms` chains of `length` joints each off the base, one after the other.
fn arms(arms: usize, length: usize) -> Vec<Option<usize>> {
    (0..arms * length)
        .map(|i| (i % length != 0).then(|| i - 1))
        .collect()
}

#[test]
fn a_serial_robot_keeps_sixteen_joints() {
    assert_eq!(joint_count(&arms(1, MAX_JOINTS)), None);
    assert_eq!(
        joint_count(&arms(1, 17)),
        Some(Problem::TooManyJoints { count: 17 })
    );
    let message = Problem::TooManyJoints { count: 17 }.to_string();
    assert_eq!(
        message,
        "17 joints; at most 16 are supported (the generated code grows as n³)"
    );
}

/// Baxter's shape (19 joints: the head, two arms of 7 with a gripper of two fingers) and
/// four arms of 16 pass; a seventeenth joint on one path, or a sixty-fifth in all, do not.
#[test]
fn a_tree_is_bounded_along_each_path_and_in_all() {
    let mut baxter = vec![None];
    for arm in [1, 10] {
        baxter.extend((arm..arm + 7).map(|j| Some(j - 1).filter(|&p| p >= arm)));
        baxter.extend([Some(arm + 6), Some(arm + 6)]);
    }
    assert_eq!(baxter.len(), 19);
    assert_eq!(joint_count(&baxter), None);
    assert_eq!(joint_count(&arms(4, MAX_JOINTS)), None);
    // The second arm's seventeenth joint (joint 34, 0-based 33) is the first past the limit.
    let mut long = arms(3, 17);
    long[..17].iter_mut().skip(1).for_each(|p| *p = None);
    assert_eq!(joint_count(&long), Some(Problem::PathTooLong { joint: 33 }));
    assert!(Problem::PathTooLong { joint: 33 }
        .to_string()
        .starts_with("joint 34 is the 17th joint on its path from the base; at most 16"));
    let many = arms(MAX_TREE_JOINTS / 4 + 1, 4);
    assert_eq!(
        joint_count(&many),
        Some(Problem::TooManyInTree { count: 68 })
    );
    assert!(Problem::TooManyInTree { count: 68 }
        .to_string()
        .starts_with("68 joints; at most 64 are supported in a tree"));
}

/// An antecedent that comes later (refused by the tree check) does not panic the count.
#[test]
fn a_later_antecedent_starts_a_path() {
    assert_eq!(joint_count(&[Some(1), None, Some(1)]), None);
}
