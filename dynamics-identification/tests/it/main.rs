//! The crate's tests, one binary: its front (`api`), and each module's numerics, a module
//! here per module of the library.
//!
//! They are integration tests rather than unit tests (`[lib] test = false` in the manifest):
//! a unit test binary is a second optimized build of the whole library, for tests that take a
//! fiftieth of a second to run.

mod api;
mod excite;
mod floating_trajectory;
mod identify;
mod lanes;
mod linear_algebra;
mod regressor;
mod sizing;
mod trajectory;
