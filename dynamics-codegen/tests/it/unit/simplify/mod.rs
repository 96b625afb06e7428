//! The tests of `dynamics_codegen::simplify`, by file.

mod bound;
mod mimic_tests;
mod prune_tests;
mod tests;
