//! The symbolic engine: exact numbers, a hash-consed expression graph, and the [`Expr`] handle
//! that traces an algorithm written over [`crate::algo::Scalar`] into the graph.

mod expr;
mod graph;
mod number;

pub use expr::Expr;
pub use graph::{Graph, Node, NodeId, Stats, Var};
pub use number::Number;
