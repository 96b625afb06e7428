//! Rigid-body algorithms written once over a [`Scalar`]: run on `f64` they evaluate the
//! dynamics numerically; run on [`crate::symbolic::Expr`] they trace the closed form into the
//! expression graph, customized to one robot.
//!
//! All of them work on a [`Chain`]: the robot re-expressed with one frame per joint, on the
//! joint's axis (the modified D-H form), which both D-H conventions convert to exactly.

mod chain;
mod crba;
mod energy;
mod rnea;
mod vector;

pub use chain::{Body, Chain, ChainJoint, DhRow, Inertial, JointKind};
pub use crba::{crba, crba_derivative};
pub use energy::{kinetic_energy, potential_energy};
pub use rnea::rnea;
pub use vector::{Mat3, V3};

use crate::symbolic::Number;
use std::ops::{Add, Mul, Neg, Sub};

/// What the algorithms compute with: `f64`, or the symbolic [`crate::symbolic::Expr`].
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
}
