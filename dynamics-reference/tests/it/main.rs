//! The reference's integration tests, one module per file, in one test binary: one link of the
//! crate and its dependencies instead of one per file. `cargo test -p dynamics-reference --test
//! it identities::` runs one file's tests.

mod common;
mod identities;
mod niku_examples;
mod random_trees;
mod reference_data;
mod tree_data;
mod tree_json;
