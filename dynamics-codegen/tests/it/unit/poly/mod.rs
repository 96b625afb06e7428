//! The tests of `dynamics_codegen::poly`, by file.

mod fold;
mod parse;
mod symbol;
