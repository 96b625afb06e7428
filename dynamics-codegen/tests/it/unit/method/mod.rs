//! The tests of `dynamics_codegen::method`, by file.

mod family;
mod tests;
