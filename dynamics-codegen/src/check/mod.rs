//! The checks of a robot that need no derivation, one pass after lowering ([`robot`]) for every
//! input of the derive and for the command-line tool: the number of joints is within
//! [`MAX_JOINTS`] (a tree's along each path, and [`MAX_TREE_JOINTS`] in all: [`joint_count`]), each link's mass and inertia tensor are ones a rigid body can have
//! ([`link`]), and each joint's actuator inertia and spring are not negative ([`drive`]), its
//! friction coefficients not negative and its smoothing velocity positive ([`friction`];
//! [`gear`] for a rotor and gear ratio, which the model does not keep: the front ends check
//! them before turning them into an actuator inertia), and a tree's joints each after its
//! antecedent, in the modified convention ([`tree`]). Each problem names the value it
//! concerns by its description-file key ([`LinkParameter::key`]); the front end's table of
//! sources places it on the tokens or at the line and column that give that value.

mod count;
mod drive;
mod eigenvalues;
mod friction;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod link;
mod tree;

pub use count::{joint_count, MAX_JOINTS, MAX_TREE_JOINTS};
pub use drive::drive;
pub use eigenvalues::eigenvalues;
pub use friction::{friction, gear, geared_inertia};
pub use link::{link, LinkParameter, LinkProblem};
pub use tree::{tree, BranchProblem};

use crate::model::Robot;

/// A problem with a whole robot.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// A serial robot of more than [`MAX_JOINTS`] joints.
    TooManyJoints {
        /// The number of joints.
        count: usize,
    },
    /// A tree of more than [`MAX_TREE_JOINTS`] joints.
    TooManyInTree {
        /// The number of joints.
        count: usize,
    },
    /// Joint `joint` (0-based) is the first joint past [`MAX_JOINTS`] along its path from the
    /// base, in a tree.
    PathTooLong {
        /// The joint's index, 0-based.
        joint: usize,
    },
    /// Joint `joint` (0-based) hangs in the tree where the algorithms cannot take it.
    Branch {
        /// The joint's index, 0-based.
        joint: usize,
        /// What is wrong with its place.
        problem: BranchProblem,
    },
    /// A physical problem with link `joint` (0-based).
    Link {
        /// The link's (and its joint's) index, 0-based.
        joint: usize,
        /// What is wrong with it.
        problem: LinkProblem,
    },
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Problem::TooManyJoints { count } => write!(
                f,
                "{count} joints; at most {MAX_JOINTS} are supported (the generated code grows as n³)"
            ),
            Problem::TooManyInTree { count } => write!(
                f,
                "{count} joints; at most {MAX_TREE_JOINTS} are supported in a tree \
                 (and {MAX_JOINTS} along any path from the base)"
            ),
            Problem::PathTooLong { joint } => write!(
                f,
                "joint {} is the {}th joint on its path from the base; at most {MAX_JOINTS} are \
                 supported along a path (the generated code grows as the cube of a path's length)",
                joint + 1,
                MAX_JOINTS + 1
            ),
            Problem::Link { joint, problem } => write!(f, "joint {}: {}", joint + 1, problem.message),
            Problem::Branch { joint, problem } => write!(f, "joint {}: {}", joint + 1, problem.message),
        }
    }
}

/// The problems of `robot`: its number of joints first ([`joint_count`]), then each link's (and its joint's
/// drive), base to tip. Link i's inertia tensor is checked unless `check_inertia[i]` is false (a missing entry checks it).
#[must_use]
pub fn robot(robot: &Robot, check_inertia: &[bool]) -> Vec<Problem> {
    let parents: Vec<Option<usize>> = (0..robot.dof()).map(|i| robot.parent(i)).collect();
    let too_many = joint_count(&parents);
    let links = robot.joints.iter().enumerate().flat_map(|(joint, j)| {
        let checked = check_inertia.get(joint).copied().unwrap_or(true);
        link(&j.link.mass, &j.link.inertia, checked)
            .into_iter()
            .chain(drive(&j.link.actuator_inertia, j.link.spring.as_ref()))
            .chain(j.link.friction.iter().flat_map(friction))
            .map(move |problem| Problem::Link { joint, problem })
    });
    let branches = tree(robot)
        .into_iter()
        .map(|(joint, problem)| Problem::Branch { joint, problem });
    too_many.into_iter().chain(branches).chain(links).collect()
}

#[cfg(test)]
mod tests {
    use super::{robot, LinkParameter, Problem, MAX_JOINTS};
    use crate::model::{Convention, Joint, JointKind, Link, Pose, Robot, Value};

    fn joint(mass: f64) -> Joint {
        let link = Link {
            mass: Value::from_f64(mass),
            inertia: [1.0, 1.0, 3.0, 0.0, 0.0, 0.0].map(Value::from_f64),
            ..Link::default()
        };
        Joint::dh(JointKind::Revolute, Default::default(), link)
    }

    fn chain(masses: &[f64]) -> Robot {
        Robot {
            name: "chain".into(),
            convention: Convention::Standard,
            gravity: Default::default(),
            joints: masses.iter().map(|m| joint(*m)).collect(),
            base: Pose::identity(),
            tool: None,
            tips: Vec::new(),
        }
    }

    #[test]
    fn joint_count_first_then_links_base_to_tip() {
        let mut masses = vec![1.0; MAX_JOINTS + 1];
        masses[2] = -1.0;
        let problems = robot(&chain(&masses), &[]);
        // Every link breaks the triangle inequality 1 + 1 < 3; link 3's mass is negative too.
        assert_eq!(problems.len(), 2 + masses.len());
        assert_eq!(
            problems[0],
            Problem::TooManyJoints {
                count: MAX_JOINTS + 1
            }
        );
        assert!(problems[0].to_string().starts_with("17 joints; at most 16"));
        let Problem::Link { joint, problem } = &problems[3] else {
            panic!("{:?}", problems[3]);
        };
        assert_eq!((*joint, problem.parameter), (2, LinkParameter::Mass));
        assert!(problems[3]
            .to_string()
            .starts_with("joint 3: the mass is negative"));
    }

    #[test]
    fn unchecked_inertia_is_skipped() {
        assert_eq!(robot(&chain(&[1.0, 1.0]), &[false, true]).len(), 1);
        assert!(robot(&chain(&[1.0]), &[false]).is_empty());
    }
}
