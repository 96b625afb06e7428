//! Integration tests of the workspace (see `tests/`), and the helpers they share:
//! [`random`], proptest strategies for random robots and states; [`interpret`], their
//! expression graph evaluated at a state; [`book`], the harness that
//! checks the generated code against the book's worked examples; [`printed`], the book's
//! printed equations parsed into exact polynomials; [`mod@reference`], the comparison with a
//! reference data file of `tests/data/`; [`robots`], the robots of that data, derived once. The helpers that the generator's and the
//! runtime's own tests need too (a seeded generator, the error measures) are in
//! `dynamics-test-support` (`tests/support`), re-exported here, because those crates cannot
//! depend on this one without a cycle.

pub mod book;
pub mod interpret;
pub mod lanes;
pub mod printed;
pub mod random;
pub mod reference;
pub mod robots;

pub use dynamics_test_support::{error_over, relative_error, Rng};
