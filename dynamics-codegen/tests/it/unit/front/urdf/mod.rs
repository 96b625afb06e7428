//! The tests of `dynamics_codegen::front::urdf`, by file.

mod tests;
