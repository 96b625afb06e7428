//! Test helpers shared by the workspace's tests, written once: a seeded random generator
//! ([`Rng`]), the relative error measures ([`error_over`], [`relative_error`]) and a scratch
//! directory removed when the test ends ([`Scratch`]).
//!
//! The crate has no dependencies, so that every crate of the workspace, the generator and the
//! runtime included, can take it as a dev-dependency: `dynamics-tests` (the integration tests)
//! depends on `dynamics-runtime`, which depends on `dynamics-macros` and `dynamics-codegen`, so
//! helpers that lived there could not be used by those crates' own tests without a cycle.
//! The error measure of the reference data, `max|a − b| / max(1, max|b|)`, is
//! `dynamics_reference::scaled_error`; random robots and states for property tests are
//! proptest strategies in `dynamics-tests` (`tests/src`).

mod error;
mod rng;
mod scratch;

pub use error::{error_over, relative_error};
pub use rng::Rng;
pub use scratch::Scratch;
