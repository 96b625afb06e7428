//! The generator's integration tests, one module per file, in one test binary: one link of the
//! crate and its dependencies instead of one per file. `cargo test -p dynamics-codegen --test it
//! fuzz_files::` runs one file's tests.

mod determinism;
mod expansion;
mod floating_base;
mod fuzz;
mod fuzz_attributes;
mod fuzz_files;
mod fuzz_urdf;
mod niku_symbolic;
mod numeric;
mod robustness;
mod unit;
mod urdf_trees;
