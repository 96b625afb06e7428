//! The tests of `dynamics_codegen::model::lower`, by file.

mod tests;
mod tree_tests;
