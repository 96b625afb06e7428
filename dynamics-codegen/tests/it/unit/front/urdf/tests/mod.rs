//! The URDF reader's tests: the real robots of `robots/urdf/`, fixed links merged against a
//! hand computation, and bad input at its line and column.

mod caps;
mod derive;
mod errors;
mod limits;
mod merging;
mod robots;
