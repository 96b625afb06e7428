//! A robot's tips: the frames whose kinematics `TipKinematics` gives, each fixed to a joint's
//! link. A URDF names them (its `tips = [..]`, or the leaf links of the tree it keeps); for a
//! description that does not, they are the leaves of the tree in joint order, each at its
//! link frame, named `link{i}` after its joint's number.

use super::{Pose, Robot};

/// A frame fixed to a link, a tip of the robot.
#[derive(Clone, Debug, PartialEq)]
pub struct Tip {
    /// Its name: the URDF link's, or `link{i}` (joint i's link, from 1).
    pub name: String,
    /// The joint whose link carries it.
    pub joint: usize,
    /// Its frame in that link's frame (the user's link frame).
    pub offset: Pose,
}

impl Robot {
    /// The tips: those the description names, else every joint that carries no other (a leaf
    /// of the tree; the last joint of a serial robot), in joint order, at its link frame.
    #[must_use]
    pub fn tip_frames(&self) -> Vec<Tip> {
        if !self.tips.is_empty() {
            return self.tips.clone();
        }
        let carries = |i: usize| (0..self.dof()).any(|j| self.parent(j) == Some(i));
        (0..self.dof())
            .filter(|&i| !carries(i))
            .map(|joint| Tip {
                name: format!("link{}", joint + 1),
                joint,
                offset: Pose::identity(),
            })
            .collect()
    }
}
