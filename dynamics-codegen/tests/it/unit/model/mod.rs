//! The tests of `dynamics_codegen::model`, by file.

mod arith;
mod frame;
mod lower;
