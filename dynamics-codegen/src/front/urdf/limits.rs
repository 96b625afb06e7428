//! The joint limits of a URDF chain: `<limit lower upper velocity effort>` of each moving joint,
//! in the robot's joint order, for the tools that plan motions within them (`dynamics excite`)
//! and the default envelope and rated torques of `simplify(...)`. The exact dynamics do not
//! use them.

use super::xml::{self, Kind, Limit};
use super::{tree, Chain};
use crate::front::errors::FileError;

/// Per joint of the robot `chain` of the URDF text makes (its moving joints, in its order),
/// the limits its `<limit>` writes. A continuous joint has no range: its `lower` and `upper`,
/// if written, are left out.
///
/// # Errors
/// What reading the robot would report about the XML, the tree or the chain, and a `<limit>`
/// value that is not a number.
pub fn joint_limits(text: &str, chain: Chain) -> Result<Vec<Limit>, Vec<FileError>> {
    let doc = xml::read(text)?;
    let tree = tree::tree(&doc)?;
    let path = tree.select(chain)?;
    Ok(path
        .joints
        .iter()
        .map(|&j| &doc.joints[j])
        .filter(|joint| joint.kind.moves())
        .map(|joint| match joint.kind {
            Kind::Continuous => Limit {
                lower: None,
                upper: None,
                ..joint.limit
            },
            _ => joint.limit,
        })
        .collect())
}
