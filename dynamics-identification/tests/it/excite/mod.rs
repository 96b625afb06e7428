//! The exciting motion's steps (`dynamics_identification::excite`).

mod design;
mod fourier;
mod limits;
mod search;
