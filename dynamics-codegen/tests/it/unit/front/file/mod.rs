//! The tests of `dynamics_codegen::front::file`, by file.

mod simplify;
mod tests;
mod tree;
