//! A free-flying base: the rigid body a tree hangs from when the robot is not fixed to the
//! ground (a legged robot, a humanoid), as Pinocchio's free-flyer root joint. The robot's
//! joints, its [`super::Robot::base`] and gravity are as for a fixed base; this adds the body
//! itself, whose inertia a fixed base never needs.

use super::{Link, Value};

/// The floating body: the base link and every link fixed to it, combined, in the base link's
/// frame (its mass, centre of mass and inertia in [`Link`]; its joint terms unused).
#[derive(Clone, Debug, PartialEq)]
pub struct FreeFlyer {
    /// The base link's name in the description.
    pub link: String,
    /// Its inertial parameters.
    pub body: Link,
    /// The gravity acceleration in the world frame (the robot's own gravity is in its frame 0,
    /// fixed to the base): `[0, 0, −9.81]` unless the description gives another.
    pub gravity: [Value; 3],
}

impl FreeFlyer {
    /// Its values: the body's, then gravity.
    pub fn values(&self) -> impl Iterator<Item = &Value> {
        self.body.values().chain(self.gravity.iter())
    }
}
