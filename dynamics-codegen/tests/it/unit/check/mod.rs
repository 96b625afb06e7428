//! The tests of `dynamics_codegen::check`, by file.

mod count;
mod drive;
mod eigenvalues;
mod friction;
mod link;
mod tests;
mod tree;
