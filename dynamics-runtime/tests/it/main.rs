//! The runtime's integration tests, one module per file, in one test binary: one link of the
//! crate and its dependencies instead of one per file. `cargo test -p dynamics-runtime --test it
//! trig::` runs one file's tests.

mod friction_functions;
mod statics;
mod trig;
mod ulp;
