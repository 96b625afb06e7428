//! The identification's steps (`dynamics_identification::identify`).

mod about_com;
mod base;
mod consistent;
mod decimate;
mod estimate;
mod filter;
mod householder;
mod model;
mod rank;
