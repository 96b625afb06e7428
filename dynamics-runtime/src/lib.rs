//! Closed-form equations of motion of serial robots, generated at compile time from a
//! Denavit-Hartenberg table.
//!
//! This crate is what generated code runs on: the [`Dynamics`] trait that `#[derive(Dynamics)]`
//! implements, and the [`Real`] scalars (`f32`, `f64`) it computes with. It is `no_std`, uses no
//! heap, and evaluates straight-line code with no matrix-product loops.
//!
//! # Glossary
//!
//! For a robot with `N` joints:
//!
//! | name | meaning | book (Niku, ch. 6) |
//! |---|---|---|
//! | `q` | joint positions: θ (rad) for a revolute joint, d (m) for a prismatic one | q_i |
//! | `qd`, `qdd` | joint velocities and accelerations | q̇_i, q̈_i |
//! | `tau` | joint torques (N·m) or forces (N) | T_i |
//! | `M(q)` | mass matrix, with actuator inertia on the diagonal | D_ij + I_i(act) |
//! | `C(q, qd)` | Coriolis matrix, C_ij = Σ_k Γ_ijk q̇_k | Σ_k D_ijk q̇_k |
//! | `g(q)` | gravity (and joint spring) torques | D_i |
//!
//! The equation of motion is `tau = M(q) qdd + C(q, qd) qd + g(q)` (eq. 6.46). `C` is built
//! from the Christoffel symbols of `M`, so `Ṁ − 2C` is skew-symmetric.
//!
//! A derived type's `equations()` prints these in the book's notation, with θ̇_i, θ̈_i written
//! `θi'`, `θi''` (`di'`, `di''` for a prismatic joint): a combining dot does not show in
//! rustdoc's code font.
//!
//! # Many states at once
//!
//! The lane types of [`lanes`] ([`F64x4`], [`F32x8`], …) are [`Real`] too: with `q: [F64x4;
//! N]`, every method evaluates four states in one call, each lane bit for bit the `f64`
//! result of its state (AVX2 or SSE2 registers on x86-64). `Real` is therefore not ordered;
//! [`RealScalar`] is the one-number `f32` and `f64`.
//!
//! # Example
//!
//! ```
#![doc = include_str!("../examples/two_link.rs")]
//! ```
//!
//! # Features
//!
//! * `std` (default): links std. Sine and cosine do not depend on it: the crate computes both
//!   at once with one shared range reduction, within 1 ulp of std and cheaper than two libm
//!   calls (`libm` beyond 2^16 rad for `f64`, 2^12 rad for `f32`). Generated code asks for four
//!   joints' at a time ([`Real::sin_cos_4`]), which x86-64 computes in vector lanes, bit for
//!   bit the same values: `f64` in SSE2 pairs in every build, in four AVX2 lanes where the
//!   build enables AVX2 (`-C target-cpu=native` on most machines); `f32` in four SSE lanes.
//! * `derive` (default): re-exports `#[derive(Dynamics)]`.
//! * `nalgebra`: the `nalgebra` module, conversions to and from nalgebra's types
//!   (`DynamicsNalgebra`: an `_na` version of every method).
#![cfg_attr(not(feature = "std"), no_std)]
// `unsafe` only to call the vector sines and cosines (`#[target_feature]` functions) and the
// lane types' intrinsics on x86-64.
#![deny(unsafe_code)]
#![warn(missing_docs)]

// First: the tables of methods and of their results that `dynamics` and `nalgebra` declare
// their traits from.
// Before `methods`, whose `for_each_method!` calls `for_each_base_method!`, which calls
// `for_each_tip_method!`, which calls `for_each_floating_method!`.
#[macro_use]
mod floating_methods;
#[macro_use]
mod tip_methods;
#[macro_use]
mod base_methods;
#[macro_use]
mod methods;
#[macro_use]
mod results;

mod derivatives;
// Before `nalgebra`, which reads its `nalgebra_result!` and `to_nalgebra!`.
#[macro_use]
mod dynamics;
// After `dynamics`, whose `array_result!` it reads.
pub mod batch;
// Public for the Python package (`python/src/configuration.rs`), which calls it on NumPy arrays.
#[doc(hidden)]
pub mod configuration;
mod contact_solve;
mod factor;
mod floating_contact_terms;
mod floating_contacts;
mod floating_kinematics;
mod floating_surface_contacts;
pub mod lanes;
#[cfg(feature = "nalgebra")]
pub mod nalgebra;
mod pose;
mod real;
mod scalars;
pub mod statics;
mod tangent;
mod trig;

#[cfg(feature = "rayon")]
pub use crate::batch::InParallel;
pub use crate::batch::{
    BatchScalar, DerivativesBatchScalar, DynamicsBaseParametersBatch, DynamicsBatch,
    DynamicsDerivativesBatch, DynamicsRegressorBatch, DynamicsSimplifiedBatch,
    FloatingContactsBatch, FloatingDynamicsBaseParametersBatch, FloatingDynamicsBatch,
    FloatingDynamicsDerivativesBatch, FloatingDynamicsRegressorBatch, TipKinematicsBatch,
};
pub use crate::contact_solve::ContactError;
pub use crate::derivatives::{ForwardDynamicsDerivatives, InverseDynamicsDerivatives};
pub use crate::dynamics::{
    Dynamics, DynamicsBaseParameters, DynamicsDerivatives, DynamicsRegressor, DynamicsSimplified,
    FloatingDynamics, FloatingDynamicsBaseParameters, FloatingDynamicsDerivatives,
    FloatingDynamicsRegressor, TipKinematics,
};
pub use crate::factor::NotPositiveDefinite;
pub use crate::floating_contact_terms::{ContactTerms, FloatingContactTerms};
pub use crate::floating_contacts::{ContactDynamics, FloatingContacts};
pub use crate::floating_kinematics::FloatingKinematics;
pub use crate::floating_surface_contacts::{ConstrainedDynamics, Contact};
pub use crate::lanes::{F32x4, F32x8, F64x2, F64x4, F64x8};
pub use crate::pose::Pose;
pub use crate::real::{Real, RealScalar};

#[cfg(feature = "derive")]
pub use dynamics_macros::Dynamics;

/// Items that generated code names. Not public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::lanes::{F32x4, F32x8, F64x2, F64x4, F64x8};
    pub use crate::real::{Real, RealScalar};
    pub use crate::tangent::{align_stack, Tangent};
    pub use core;

    /// Converts a robot parameter (a struct field of type `f32` or `f64`) to the scalar type
    /// of the evaluation.
    #[inline(always)]
    #[must_use]
    pub fn param<T: Real, F: Into<f64>>(value: F) -> T {
        T::from_f64(value.into())
    }
}

/// `[0, 1, …, L − 1]`: the default of `DynamicsRegressor::JOINT_ROWS`, each joint's columns in
/// its own row (a robot without mimic joints). Not public API.
#[doc(hidden)]
#[must_use]
pub const fn identity_rows<const L: usize>() -> [usize; L] {
    let mut rows = [0; L];
    let mut i = 0;
    while i < L {
        rows[i] = i;
        i += 1;
    }
    rows
}
