//! The checks of a kinematic tree's shape, which the algorithms rely on: every antecedent is an
//! earlier joint (so that a joint's rates follow from its antecedent's, computed before it),
//! and a tree is given in the modified D-H convention (Khalil and Kleinfinger's table: a
//! standard table has no antecedent column and no γ, b); and each mimic joint follows another
//! joint of its kind that is not a mimic joint.

use crate::model::{Convention, Robot};

/// Joint `joint`'s place in the tree is not one the algorithms can take; the message says why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BranchProblem {
    /// What is wrong.
    pub message: String,
}

/// The problems of `robot`'s branches, each with its joint (0-based).
#[must_use]
pub fn tree(robot: &Robot) -> Vec<(usize, BranchProblem)> {
    let mut problems = Vec::new();
    for (j, joint) in robot.joints.iter().enumerate() {
        let Some(branch) = &joint.branch else {
            continue;
        };
        if let Some(parent) = branch.parent.filter(|&p| p >= j) {
            let message = format!(
                "its antecedent is joint {}, which is not an earlier joint: number the joints \
                 so that each comes after the joint that carries it",
                parent + 1
            );
            problems.push((j, BranchProblem { message }));
        }
    }
    if robot.is_tree() && robot.convention == Convention::Standard {
        let first = (0..robot.dof()).find(|&i| robot.parent(i) != i.checked_sub(1));
        let message = "a kinematic tree is given in the modified D-H convention \
                       (Khalil-Kleinfinger): a standard table has no antecedent"
            .to_string();
        problems.extend(first.map(|j| (j, BranchProblem { message })));
    }
    problems.extend(mimics(robot));
    problems
}

/// The problems of the mimic joints: each follows another joint of the robot, of its own kind
/// (Pinocchio's rule), that is not a mimic joint itself.
fn mimics(robot: &Robot) -> Vec<(usize, BranchProblem)> {
    let mut problems = Vec::new();
    for (m, joint) in robot.joints.iter().enumerate() {
        let Some(mimic) = &joint.mimic else { continue };
        let j = mimic.joint;
        let message = match robot.joints.get(j) {
            None => format!(
                "it follows joint {}, which the robot does not have ({} joints)",
                j + 1,
                robot.dof()
            ),
            Some(_) if j == m => "it follows itself: a mimic joint follows another joint".into(),
            Some(followed) if followed.mimic.is_some() => format!(
                "it follows joint {}, a mimic joint itself: a mimic joint follows a joint that \
                 is not",
                j + 1
            ),
            Some(followed) if followed.kind != joint.kind => format!(
                "it follows joint {}, which is not of its kind (revolute or prismatic): a mimic \
                 joint follows a joint of its own kind",
                j + 1
            ),
            Some(_) => continue,
        };
        problems.push((m, BranchProblem { message }));
    }
    problems
}
