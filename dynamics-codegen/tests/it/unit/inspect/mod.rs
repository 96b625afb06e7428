//! The tests of `dynamics_codegen::inspect`, by file.

mod branches;
mod label;
mod tests;
