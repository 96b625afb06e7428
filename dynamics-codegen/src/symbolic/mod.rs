//! The symbolic engine: exact numbers, a hash-consed expression graph, and the [`Expr`] handle
//! that traces an algorithm written over [`crate::algo::Scalar`] into the graph.

mod calculus;
mod expr;
mod graph;
mod node;
mod number;

pub use calculus::Wrt;
pub use expr::Expr;
pub use graph::{Graph, Stats};
pub use node::{Node, NodeId, Var, WRENCH};
pub use number::Number;
