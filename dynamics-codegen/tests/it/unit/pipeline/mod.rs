//! The tests of `dynamics_codegen::pipeline`, by file.

mod c_header;
mod evaluate;
mod families;
mod readable;
mod tests;
