//! Where each value of a lowered robot came from: every front end lowers its input to a
//! [`Robot`] and this table, so that the checks that run after lowering ([`crate::check::robot`])
//! place each problem on the value it concerns, whatever the input looked like. A place is the
//! attribute's tokens (their spans) or a line and column of a file.

use crate::check::{Problem, MAX_JOINTS, MAX_TREE_JOINTS};
use crate::front::simplify::given::Given;
use crate::model::{FreeFlyer, Robot};
use proc_macro2::Span;
use std::collections::BTreeMap;

/// A 1-based line and column in a file.
pub type At = (usize, usize);

/// The tokens an attribute writes a value with: its first and last.
pub type Tokens = (Span, Span);

/// Where each value of a robot is written: per joint, the place of each key that gives one.
///
/// The keys are those of a description file (`mass`, `inertia`, `spring_stiffness`,
/// `friction_viscous`, `type` for the joint itself, ...), whatever the input: a check's
/// problem names its key once ([`crate::check::LinkParameter::key`]), and every front end
/// files its places under the same keys.
#[derive(Clone, Debug)]
pub struct Sources<P> {
    /// Per joint, base to tip, the place of each key it gives.
    pub joints: Vec<BTreeMap<String, P>>,
    /// Where `gravity` is given.
    pub gravity: Option<P>,
    /// Where a file's `[simplify]` table (under the key `simplify`) and each of its keys are.
    pub simplify: BTreeMap<String, P>,
}

impl<P> Default for Sources<P> {
    fn default() -> Self {
        Sources {
            joints: Vec::new(),
            gravity: None,
            simplify: BTreeMap::new(),
        }
    }
}

impl<P> Sources<P> {
    /// Where joint `joint` (0-based) gives `key`, if it does.
    #[must_use]
    pub fn get(&self, joint: usize, key: &str) -> Option<&P> {
        self.joints.get(joint)?.get(key)
    }

    /// Where `problem` is: the value it concerns, or for a robot with too many joints the first
    /// joint past the limit (its entry): in all, or along a path of a tree.
    #[must_use]
    pub fn place(&self, problem: &Problem) -> Option<&P> {
        match problem {
            Problem::TooManyJoints { .. } => self.get(MAX_JOINTS, "type"),
            Problem::TooManyInTree { .. } => self.get(MAX_TREE_JOINTS, "type"),
            Problem::PathTooLong { joint } => self.get(*joint, "type"),
            Problem::Link { joint, problem } => self.get(*joint, problem.parameter.key()),
            Problem::Branch { joint, .. } => self.get(*joint, "type"),
        }
    }
}

/// Where a file writes each value: 1-based lines and columns.
pub type Positions = Sources<At>;

impl Positions {
    /// `path:line:col: ` where the file gives joint `joint`'s `key`, or `path: ` when it does
    /// not say: the prefix of a message about that value.
    #[must_use]
    pub fn at(&self, path: &str, joint: usize, key: &str) -> String {
        prefix(path, self.get(joint, key))
    }

    /// A check's problem as a message that points at the value it concerns in the file
    /// `path` (`path:line:col: joint 2: the mass is negative (-1): ...`).
    #[must_use]
    pub fn describe(&self, path: &str, problem: &Problem) -> String {
        format!("{}{problem}", prefix(path, self.place(problem)))
    }
}

/// `path:line:col: `, or `path: ` without a position.
pub(super) fn prefix(path: &str, at: Option<&At>) -> String {
    at.map_or_else(
        || format!("{path}: "),
        |(line, column)| format!("{path}:{line}:{column}: "),
    )
}

/// A robot lowered from its input, with what the input says about checking it and where it
/// gives each value.
pub struct Lowered<P> {
    /// The robot.
    pub robot: Robot,
    /// Per joint, whether its inertia tensor is checked (`check_inertia = false` opts out).
    pub check_inertia: Vec<bool>,
    /// Where each value is given, so that the checks after lowering can point at it.
    pub sources: Sources<P>,
    /// A description file's `[simplify]`, to be resolved once the robot is known.
    pub simplify: Option<Given<P>>,
    /// A description file's `[floating]`: the body of a robot on a free-flying base, in its
    /// base frame, and the file's gravity as written (in the world frame).
    pub floating: Option<FreeFlyer>,
}

/// A robot read from a file, with where the file writes each value.
pub type Loaded = Lowered<At>;

impl Loaded {
    /// A check's problem as a message that points at the value it concerns in the file
    /// `path` (`path:line:col: joint 2: the mass is negative (-1): ...`).
    #[must_use]
    pub fn describe(&self, path: &str, problem: &Problem) -> String {
        self.sources.describe(path, problem)
    }
}
