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
