//! Rigid-body algorithms written once over a [`Scalar`]: run on `f64` they evaluate the
//! dynamics numerically; run on [`crate::trace::Expr`] they trace the closed form into the
//! expression graph, customized to one robot.
//!
//! All of them work on a [`Chain`]: the robot re-expressed with one frame per joint, on the
//! joint's axis (the modified D-H form), which both D-H conventions convert to exactly.

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod body;
mod chain;
mod coriolis;
mod crba;
mod energy;
mod floating;
#[cfg(test)]
mod floating_tests;
mod gravity;
mod kinematics;
mod ldlt;
mod projection;
mod regroup;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod rnea;
mod robot;
mod runs;
#[cfg(test)]
pub(crate) mod tree_tests;
mod vector;

pub use crate::model::JointKind;
pub use body::Body;
pub use chain::{Chain, ChainJoint, DhRow, Inertial, Pre};
pub use coriolis::coriolis_matrix;
pub use crba::{crba, crba_derivative};
pub use energy::{kinetic_energy, potential_energy};
pub use floating::{
    floating_crba, floating_gravity, floating_rnea, quaternion_rotation, spatial_inertia,
    FloatingBase,
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

/// A 5-joint arm with arbitrary twists, offsets and inertias, joint 3 prismatic: the
/// algorithms' unit tests check each other on it.
#[cfg(test)]
pub(crate) fn test_chain(q: &[f64]) -> Chain<f64> {
    let kinds = [
        JointKind::Revolute,
        JointKind::Revolute,
        JointKind::Prismatic,
        JointKind::Revolute,
        JointKind::Revolute,
    ];
    let mut rows = Vec::new();
    let mut links = Vec::new();
    for (i, (&kind, &qi)) in kinds.iter().zip(q).enumerate() {
        let x = i as f64;
        let (theta, d) = match kind {
            JointKind::Revolute => (qi + 0.1 * x, 0.05 + 0.02 * x),
            JointKind::Prismatic => (0.4, qi + 0.1),
        };
        let alpha = 0.7 - 0.45 * x;
        rows.push(DhRow {
            kind,
            sin_theta: theta.sin(),
            cos_theta: theta.cos(),
            d,
            a: 0.3 - 0.05 * x,
            sin_alpha: alpha.sin(),
            cos_alpha: alpha.cos(),
        });
        links.push(Inertial {
            mass: 1.0 + 0.3 * x,
            com: V3::new(-0.1 + 0.02 * x, 0.03, 0.05 - 0.01 * x),
            inertia: [0.05, 0.04 + 0.01 * x, 0.03, 0.004, -0.002, 0.001 * x],
        });
    }
    Chain::standard(&rows, &links)
}

/// A 7-joint arm with runs of parallel revolute joints (2-3-4 and 5-6) and a prismatic
/// last joint; with `symmetric_tip`, it ends at joint 6, whose link is axially symmetric.
#[cfg(test)]
pub(crate) fn parallel_chain(q: &[f64], symmetric_tip: bool) -> Chain<f64> {
    let alphas = [std::f64::consts::FRAC_PI_2, 0.0, 0.0, -0.7, 0.0, 0.0, 0.3];
    let joints = if symmetric_tip { 6 } else { 7 };
    let mut rows = Vec::new();
    let mut links = Vec::new();
    for (i, (&alpha, &qi)) in alphas.iter().zip(q).take(joints).enumerate() {
        let x = i as f64;
        let kind = if i == 6 {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        };
        let (theta, d) = match kind {
            JointKind::Revolute => (qi + 0.2 * x, 0.04 * x),
            JointKind::Prismatic => (0.3, qi),
        };
        rows.push(DhRow {
            kind,
            sin_theta: theta.sin(),
            cos_theta: theta.cos(),
            d,
            a: 0.25 - 0.03 * x,
            sin_alpha: alpha.sin(),
            cos_alpha: alpha.cos(),
        });
        let tip = symmetric_tip && i == 5;
        links.push(Inertial {
            mass: 1.0 + 0.2 * x,
            com: if tip {
                V3::new(0.0, 0.0, 0.05)
            } else {
                V3::new(-0.1 + 0.02 * x, 0.03, 0.05)
            },
            inertia: if tip {
                [0.02, 0.02, 0.01, 0.0, 0.0, 0.0]
            } else {
                [0.05, 0.04 + 0.01 * x, 0.03, 0.004, -0.002, 0.001 * x]
            },
        });
    }
    // The standard table's last twist is not a joint's: the tip's link keeps its axes.
    if symmetric_tip {
        rows[5].sin_alpha = 0.0;
        rows[5].cos_alpha = 1.0;
    }
    Chain::standard(&rows, &links)
}
