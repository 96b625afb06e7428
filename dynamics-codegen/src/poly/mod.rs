//! The polynomial engine: the graph's closed forms expanded into an exact canonical form, a
//! sparse polynomial with rational coefficients in the joints' sines and cosines (`S1`, `C12`),
//! prismatic positions, velocities, accelerations and parameters, with `S² = 1 − C²` applied,
//! so that two expressions are equal exactly when their canonical forms are.
//!
//! * [`Sym`] and [`Monomial`]: the vocabulary, a symbol and a product of symbols;
//! * [`Poly`]: the polynomial and its arithmetic (`polynomial`), read from text for tests (`parse`);
//! * [`Expander`]: graph nodes expanded within [`Limits`] (`expand`), their sines and cosines
//!   of sums folded back (`C1 C2 − S1 S2` → `C12`, an identity; `fold`).
//!
//! Two stages read it: the simplified models (`crate::simplify`), which bound and prune its
//! terms, and the printer of readable equations (`crate::inspect`), which arranges them.
//! Code is never emitted from it: the expanded forms grow fast with the joints, the graph
//! stays shared.

mod expand;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod fold;
mod monomial;
mod parse;
mod polynomial;
mod symbol;

pub use expand::{Expander, Limits};
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub use fold::fold_trig;
pub use monomial::Monomial;
pub use polynomial::Poly;
pub use symbol::{AngleSum, MimicAngle, Sym};
