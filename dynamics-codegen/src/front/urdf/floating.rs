//! The floating body of a URDF on a free-flying base: the base link (the root link, or the one
//! named) and every link fixed to it, below it through fixed joints, combined into one rigid
//! body in the base link's frame (`inertial`), as Pinocchio's free flyer carries them.

use super::inertial::Body;
use super::tree::Tree;
use super::xml;
use crate::front::errors::FileError;
use crate::model::{FreeFlyer, Link, Pose, Value};
use crate::symbolic::Number;

/// The floating body of the URDF text `text` with base link `base` (the root link if `None`).
///
/// # Errors
/// Malformed XML, a tree the joints do not make, an unknown `base` link.
pub fn free_flyer(text: &str, base: Option<&str>) -> Result<FreeFlyer, Vec<FileError>> {
    let doc = xml::read(text)?;
    let tree = super::tree::tree(&doc)?;
    let base = tree.base(base)?;
    let mut parts = Vec::new();
    fixed_parts(&tree, base, Pose::identity(), &mut parts);
    let body = Body::combine(&parts);
    Ok(FreeFlyer {
        link: doc.links[base].name.clone(),
        body: Link {
            mass: body.mass,
            com: body.com,
            inertia: body.inertia,
            ..Link::default()
        },
        // As the robot's default, exact.
        gravity: ["0", "0", "-9.81"]
            .map(|x| Number::parse_decimal(x).map_or_else(Value::zero, Value::num)),
    })
}

/// `link` at `pose` in the base frame, and every link fixed below it.
fn fixed_parts(tree: &Tree, link: usize, pose: Pose, parts: &mut Vec<Body>) {
    parts.push(Body::part(tree.doc.links[link].inertial.as_ref(), &pose));
    for &j in tree.children(link) {
        let joint = &tree.doc.joints[j];
        if !joint.kind.moves() {
            // URDF angles are numbers: the placement always has a pose.
            let placed = pose.then(&joint.origin.pose().unwrap_or_default());
            fixed_parts(tree, tree.child(j), placed, parts);
        }
    }
}
