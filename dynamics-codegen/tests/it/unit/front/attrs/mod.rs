//! The tests of `dynamics_codegen::front::attrs`, by file.

mod tree;
