//! The generator's tests of its modules' insides (once `#[cfg(test)]` modules of its library),
//! by source module: `cargo test -p dynamics-codegen --test it unit::algo::` runs
//! `src/algo`'s. Built in this binary, the library is compiled once, optimized, for the
//! derive and every test; a unit test binary compiled it a second time.

mod algo;
mod check;
mod emit;
mod emit_c;
mod front;
mod identifiers;
mod inspect;
mod method;
mod model;
mod numeric;
mod pipeline;
mod poly;
mod simplify;
mod symbolic;
mod trace;
