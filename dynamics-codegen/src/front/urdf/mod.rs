//! URDF input: `#[dynamics(urdf = "robots/ur10.urdf", base = "base_link", tip = "tool0")]`
//! and the command line's `ROBOT.urdf --base .. --tip ..`.
//!
//! The file is read with `roxmltree`, which keeps every element's position, so that each
//! error names `file:line:col` (`xml`). The serial chain from the base link to the tip link,
//! or the tree of the branches below the base, is found in the joint tree (`tree`,
//! `select`); each moving joint becomes a joint of the robot given by
//! its frame `P_i · Rot(u_i, q_i)` (`P_i` its `<origin>` after the fixed joints before it,
//! `u_i` its unit `<axis>`), its link the rigid body of its child link and every link fixed to
//! it, combined exactly (`inertial`), and its `<dynamics damping friction>` its viscous and
//! Coulomb friction (`robot`). The robot is then lowered to its own modified D-H table, as
//! every robot given by joint frames is. The joints' `<limit>`s are read apart, for tools that
//! plan motions (`limits`).

mod floating;
mod inertial;
mod leaves;
mod limits;
mod mimic;
mod robot;
mod select;
mod tree;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod xml;

use super::errors::FileError;
use super::sources::{Loaded, Positions};
use crate::check::{joint_count, Problem, MAX_JOINTS, MAX_TREE_JOINTS};
use crate::model::{FrameProblem, Robot};
pub use floating::free_flyer;
pub use leaves::moving_leaves;
pub use limits::joint_limits;
pub use xml::Limit;

/// Which joints of the URDF to take: the link fixed to the ground, and the serial path to one
/// link (`tip`) or the branches to some (`tips`), by name; by default every moving joint
/// below the base.
#[derive(Clone, Copy, Debug, Default)]
pub struct Chain<'a> {
    /// The link fixed to the ground; default: the root link.
    pub base: Option<&'a str>,
    /// The last link of a serial chain: the path from the base to it, refused if a moving
    /// joint branches off it.
    pub tip: Option<&'a str>,
    /// The links the branches kept lead to (empty: every branch); what moves off them is cut
    /// off.
    pub tips: &'a [&'a str],
}

/// Reads the chain `chain` of the URDF text of the file `path` as a robot lowered to its D-H
/// table, with where each joint's values are written. `check_inertia = false` skips the
/// inertia checks of the links.
///
/// # Errors
/// Every problem found, each at its line and column: malformed XML, an unknown link, a chain
/// to a `tip` that is not serial, a `tips` link not below the base, a zero or non-unit axis, a negative mass or friction coefficient, an
/// inertia a rigid body cannot have.
pub fn load_urdf(
    path: &str,
    text: &str,
    chain: Chain,
    check_inertia: bool,
) -> Result<Loaded, Vec<FileError>> {
    let doc = xml::read(text)?;
    let tree = tree::tree(&doc)?;
    let path_joints = tree.select(chain)?;
    too_many_joints(&tree, &path_joints.joints)?;
    let stem = std::path::Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str());
    let name = doc
        .name
        .clone()
        .or(stem.map(str::to_string))
        .unwrap_or_else(|| "robot".into());
    let (mut robot, positions) = robot::build(&tree, &path_joints, name, check_inertia)?;
    if robot.joints.is_empty() {
        let message =
            "no joint moves between the base and the tip: choose a `tip` further from the base";
        return Err(vec![xml::error(doc.at, message)]);
    }
    lower(&mut robot).map_err(|problems| {
        problems
            .into_iter()
            .map(|p| {
                let at = positions
                    .get(p.joint)
                    .and_then(|keys| keys.get("type"))
                    .copied();
                FileError {
                    message: format!("joint {}: {}", p.joint + 1, p.message),
                    line: at.map(|a| a.0),
                    column: at.map(|a| a.1),
                    about: None,
                }
            })
            .collect::<Vec<_>>()
    })?;
    let dof = robot.dof();
    Ok(Loaded {
        robot,
        check_inertia: vec![check_inertia; dof],
        sources: Positions {
            joints: positions,
            ..Positions::default()
        },
        simplify: None,
        // The URDF's floating body is its root link's (`urdf::free_flyer`).
        floating: None,
    })
}

/// More moving joints than a robot may have, at the first one past the limit (in all, or along
/// a tree's path): the error `check::robot` gives, found before thousands of joints are built
/// and lowered for nothing.
fn too_many_joints(tree: &tree::Tree, path: &[usize]) -> Result<(), Vec<FileError>> {
    let doc = tree.doc;
    // Per URDF joint, the index among the moving ones of the nearest moving joint at or above it
    // (the path is depth first: a joint's ancestors come before it).
    let mut nearest: Vec<Option<usize>> = vec![None; doc.joints.len()];
    let (mut moving, mut parents) = (Vec::new(), Vec::new());
    for &j in path {
        let above = tree.parent[tree.parent_link(j)].and_then(|p| nearest[p]);
        nearest[j] = above;
        if doc.joints[j].kind.moves() {
            parents.push(above);
            nearest[j] = Some(moving.len());
            moving.push(&doc.joints[j]);
        }
    }
    let Some(problem) = joint_count(&parents) else {
        return Ok(());
    };
    let first_past = match problem {
        Problem::TooManyJoints { .. } => MAX_JOINTS,
        Problem::TooManyInTree { .. } => MAX_TREE_JOINTS,
        Problem::PathTooLong { joint } => joint,
        Problem::Link { joint, .. } | Problem::Branch { joint, .. } => joint,
    };
    let at = moving.get(first_past).map_or(doc.at, |j| j.at);
    Err(vec![xml::error(at, problem.to_string())])
}

/// The robot lowered to its own modified D-H table.
fn lower(robot: &mut Robot) -> Result<(), Vec<FrameProblem>> {
    crate::model::lower_frames(robot)
}
