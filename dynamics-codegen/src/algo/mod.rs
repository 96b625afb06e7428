//! Rigid-body algorithms written once over a [`Scalar`]: run on `f64` they evaluate the
//! dynamics numerically; run on [`crate::trace::Expr`] they trace the closed form into the
//! expression graph, customized to one robot.
//!
//! All of them work on a [`Chain`]: the robot re-expressed with one frame per joint, on the
//! joint's axis (the modified D-H form), which both D-H conventions convert to exactly.

mod aba;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod body;
mod chain;
mod coriolis;
mod crba;
mod energy;
mod floating;
mod floating_kinematics;
mod gravity;
mod kinematics;
mod ldlt;
mod projection;
mod regroup;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod rnea;
mod robot;
mod runs;
mod vector;

pub use crate::model::JointKind;
pub use aba::{floating_aba, Articulated};
pub use body::Body;
pub use chain::{Chain, ChainJoint, DhRow, Inertial, Pre};
pub use coriolis::coriolis_matrix;
pub use crba::{crba, crba_derivative};
pub use energy::{kinetic_energy, potential_energy};
pub use floating::{
    floating_crba, floating_gravity, floating_rnea, quaternion_rotation, spatial_inertia,
    FloatingBase,
};
pub use floating_kinematics::{
    centroidal, centroidal_bias, floating_frame, Centroidal, FloatingFrame,
};
pub use gravity::gravity_torques;
pub use kinematics::{
    acceleration_bias_in_base, in_hand_axes, jacobian_in_base, jacobian_in_hand, joint_torques,
    kinematics, tip_kinematics, Frame, Jacobian, Kinematics,
};
pub use ldlt::Ldlt;
pub use projection::{projected_torques, LinkFrame, LinkFrames, Twist};
pub use rnea::{rnea, rnea_from, BaseMotion, Wrench};
pub use robot::RobotScalars;
pub use runs::WrenchCarrier;
pub use vector::{Mat3, V3};

use crate::symbolic::Number;
use std::ops::{Add, Mul, Neg, Sub};

/// What the algorithms compute with: `f64`, or the symbolic [`crate::trace::Expr`].
pub trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// A constant, in the same context as `self` (the same graph for a symbolic scalar).
    #[must_use]
    fn constant(self, c: Number) -> Self;

    /// Zero, in the context of `self`.
    #[must_use]
    fn zero(self) -> Self {
        self.constant(Number::ZERO)
    }

    /// Whether `self` is a known constant (always, for a number): the algorithms pick forms
    /// that fold away for constants.
    fn is_constant(self) -> bool;

    /// Whether `self` is exactly zero (a known constant zero, for a symbolic scalar).
    fn is_zero(self) -> bool;

    /// One, in the context of `self`.
    #[must_use]
    fn one(self) -> Self {
        self.constant(Number::ONE)
    }

    /// `1 / self`. A symbolic constant zero has none: zero stands in, so a caller dividing by
    /// a value that may be zero checks it (as the LDLᵀ's pivots are).
    #[must_use]
    fn recip(self) -> Self;
}

impl Scalar for f64 {
    fn constant(self, c: Number) -> f64 {
        c.to_f64()
    }

    fn is_constant(self) -> bool {
        true
    }

    fn is_zero(self) -> bool {
        self == 0.0
    }

    fn recip(self) -> f64 {
        1.0 / self
    }
}
