//! The tests of `dynamics_codegen::front`, by file.

mod angle;
mod attrs;
mod file;
mod parent;
mod urdf;
mod value;
