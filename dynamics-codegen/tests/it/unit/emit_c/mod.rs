//! The tests of `dynamics_codegen::emit_c`, by file.

mod batch;
mod expr;
mod function;
mod kernels;
mod tests;
