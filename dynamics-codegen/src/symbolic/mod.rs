//! The symbolic engine: exact numbers, a hash-consed expression graph simplified as it is
//! built, and differentiation on it. It knows nothing of robots; `trace` runs the algorithms on
//! it through its `Expr` handle.

mod calculus;
mod graph;
pub mod modular;
mod node;
mod number;

pub use calculus::Wrt;
pub use graph::{Graph, Stats};
pub use node::{Node, NodeId, Var, WRENCH};
pub use number::Number;
