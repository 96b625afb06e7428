//! The tests of `dynamics_codegen::trace::base_parameters`, by file.

mod coefficients;
mod exact;
