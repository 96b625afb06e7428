//! The symbolic engine: exact numbers, a hash-consed expression graph simplified as it is
//! built, differentiation on it, and a tape that evaluates some of its outputs in `f64`. It
//! knows nothing of robots; `trace` runs the algorithms on it through its `Expr` handle.

mod calculus;
mod graph;
mod hasher;
pub mod modular;
mod node;
mod number;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod tangent;
mod tape;

pub use calculus::Wrt;
pub use graph::{Graph, Stats};
pub use node::{Node, NodeId, Var, WRENCH};
pub use number::Number;
pub use tangent::{Lane, Of, Tangents, Term, BLOCK, QUARTER_BLOCK};
pub use tape::{Tape, TapeScalar};
