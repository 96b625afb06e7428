//! Joint frames given URDF style, as a fixed placement followed by a motion about or along an
//! axis, and rigid poses between frames.
//!
//! A joint given this way has link frame i = `P_i · Rot(u_i, q_i)` (revolute) or
//! `P_i · Trans(q_i u_i)` (prismatic) in link frame i − 1, with `P_i` the placement
//! `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`. The generator works on the robot's own D-H table,
//! which the front end derives from these frames; [`Pose`]s relate the two.

use super::Value;

/// A fixed placement, as URDF's `<origin xyz rpy>`: `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`
/// with `rpy = [roll, pitch, yaw]` in radians.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Placement {
    /// Translation.
    pub xyz: [Value; 3],
    /// Roll, pitch, yaw about the fixed x, y, z axes.
    pub rpy: [Value; 3],
}

/// Joint i as the user gave it, URDF style: `origin` places the joint frame in link frame
/// i − 1 (the base frame for joint 1), and the joint turns about or slides along the unit
/// `axis`, in joint-frame axes. At q = 0 the joint frame is link frame i, the frame of link
/// i's inertial parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisFrame {
    /// The placement of the joint frame.
    pub origin: Placement,
    /// The unit axis, in the joint frame.
    pub axis: [Value; 3],
}

/// A rigid transform `x ↦ rotation · x + translation` with an exact rotation matrix (rows).
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// The rotation matrix, row by row.
    pub rotation: [[Value; 3]; 3],
    /// The translation.
    pub translation: [Value; 3],
}

impl Pose {
    /// The identity.
    #[must_use]
    pub fn identity() -> Pose {
        let one = || Value::Num(crate::symbolic::Number::ONE);
        Pose {
            rotation: [
                [one(), Value::zero(), Value::zero()],
                [Value::zero(), one(), Value::zero()],
                [Value::zero(), Value::zero(), one()],
            ],
            translation: Default::default(),
        }
    }
}

impl Default for Pose {
    fn default() -> Pose {
        Pose::identity()
    }
}
