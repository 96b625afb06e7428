//! System identification: the estimate of a model linear in its parameters,
//! `τ = Y(q, q̇, q̈) π`, from measured motions and torques.

pub mod estimate;
pub mod filter;
pub mod householder;
pub mod measured;
pub mod rank;
pub mod singular;
