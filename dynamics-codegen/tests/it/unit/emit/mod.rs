//! The tests of `dynamics_codegen::emit`, by file.

mod expr;
mod plan;
mod sum_order;
mod sums;
mod tip_names;
