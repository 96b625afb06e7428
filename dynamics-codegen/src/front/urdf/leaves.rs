//! The leaf links of a URDF below a link: what a floating base's frames must keep, so that
//! naming some frames (`tips = [..]`) cuts no branch off the robot that flies.

use super::tree::tree;
use super::xml;

/// The links below `base` (the root link if `None`) that carry no joint and have a moving
/// joint on their path from `base`, in the file's order; none if the file cannot be read (its
/// errors are told where it is loaded).
#[must_use]
pub fn moving_leaves(text: &str, base: Option<&str>) -> Vec<String> {
    let Ok(doc) = xml::read(text) else {
        return Vec::new();
    };
    let Ok(tree) = tree(&doc) else {
        return Vec::new();
    };
    let Ok(base) = tree.base(base) else {
        return Vec::new();
    };
    (0..doc.links.len())
        .filter(|&link| tree.children(link).is_empty())
        .filter(|&link| {
            let path = tree.ancestors(link);
            let start = path.iter().position(|&j| tree.parent_link(j) == base);
            start.is_some_and(|s| path[s..].iter().any(|&j| doc.joints[j].kind.moves()))
        })
        .map(|link| doc.links[link].name.clone())
        .collect()
}
