//! The limits on a robot's number of joints. What the generated code grows with is the length
//! of the paths from the base: a serial arm's M, C and derivatives take about n³ operations
//! along its one path, and a tree's joint only meets its own ancestors (M's nonzeros are
//! along the ancestry), so a tree is bounded along each path by the serial limit
//! ([`MAX_JOINTS`]) and in all by [`MAX_TREE_JOINTS`], the joints an angle sum of the readable
//! equations can name (`poly::symbol::AngleSum` is a set of 64).

use super::Problem;

/// The most joints a serial robot may have, and a tree along any path from the base: the
/// generated code grows about as the cube of a path's length, and sixteen joints keep a derive
/// in the time of an ordinary build.
pub const MAX_JOINTS: usize = 16;

/// The most joints a tree may have in all (at most [`MAX_JOINTS`] of them along a path).
pub const MAX_TREE_JOINTS: usize = 64;

/// The first limit that the robot whose joint i hangs off joint `parents[i]` (`None`: the
/// base) passes, if any: a serial robot's ([`Problem::TooManyJoints`]), then a tree's count
/// ([`Problem::TooManyInTree`]), then the first joint, in order, that is the
/// `MAX_JOINTS + 1`-th on its path from the base ([`Problem::PathTooLong`]). An antecedent that
/// is not an earlier joint (which `tree` reports) starts a path of its own here.
#[must_use]
pub fn joint_count(parents: &[Option<usize>]) -> Option<Problem> {
    let count = parents.len();
    let serial = parents
        .iter()
        .enumerate()
        .all(|(i, p)| *p == i.checked_sub(1));
    if serial {
        return (count > MAX_JOINTS).then_some(Problem::TooManyJoints { count });
    }
    if count > MAX_TREE_JOINTS {
        return Some(Problem::TooManyInTree { count });
    }
    let mut length = vec![0usize; count];
    for (joint, parent) in parents.iter().enumerate() {
        let above = parent.filter(|&p| p < joint).map_or(0, |p| length[p]);
        length[joint] = above + 1;
        if length[joint] > MAX_JOINTS {
            return Some(Problem::PathTooLong { joint });
        }
    }
    None
}
