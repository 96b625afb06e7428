//! System identification: the estimate of a model linear in its parameters,
//! `τ = Y(q, q̇, q̈) π`, from measured motions and torques (`dynamics identify`,
//! [`crate::identify()`]).
//!
//! * [`model`]: the regressor of a robot's graph, evaluated at a sample;
//! * [`base`]: that model for a robot's base parameters;
//! * [`source`]: the samples, streamed or filtered ([`filter`]);
//! * [`rows`]: each sample's equations, filtered and decimated alike ([`decimate`]) from a
//!   filtered source;
//! * [`measured`]: one triangular factor per joint ([`householder`]);
//! * [`estimate`]: the identifiable parameters ([`rank`]), two-step weighted least squares,
//!   standard deviations, condition number ([`crate::linear_algebra`]);
//! * [`consistent`]: the physically consistent estimate beside it (each link's
//!   [`pseudo_inertia`] positive semidefinite), its links as a description gives bodies
//!   ([`about_com`]);
//! * [`predict`]: the torques an estimate predicts, on the data of the fit or on others.

pub mod about_com;
pub mod base;
pub mod consistent;
pub mod decimate;
pub mod estimate;
pub mod filter;
pub mod householder;
pub mod measured;
pub mod model;
pub mod predict;
pub mod pseudo_inertia;
pub mod rank;
pub mod rows;
pub mod source;
