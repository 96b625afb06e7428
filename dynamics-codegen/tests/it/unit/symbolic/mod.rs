//! The tests of `dynamics_codegen::symbolic`, by file.

mod calculus;
mod graph;
mod modular;
mod number;
mod tangent;
mod tape;
