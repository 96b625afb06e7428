//! Operation counting: the multiplications, additions, negations, divisions and sines and
//! cosines of an emitted function once inlined, and its depth, the longest chain of dependent
//! operations from the inputs to a result.

use super::emitter::Emitter;
use super::parts::OpCount;
use super::sums::Sums;
use crate::symbolic::{Node, NodeId, Var};
use crate::trace::Equations;

/// Operation counts of the code computing `outputs`, shared parts included: what a function
/// costs once the compiler has inlined the configuration and dropped what it does not read.
#[must_use]
pub fn count(eq: &Equations, outputs: &[NodeId]) -> OpCount {
    let mut e = Emitter::new(eq, None);
    e.mark(outputs);
    let mut ops = OpCount::default();
    for &o in outputs {
        ops.depth = ops.depth.max(e.depth(o) as usize);
    }
    for (id, node) in eq.graph.nodes() {
        if !e.needed[id.index()] {
            continue;
        }
        match node {
            Node::Add(..) => ops.add += 1,
            Node::Mul(..) => ops.mul += 1,
            Node::Neg(_) => ops.neg += 1,
            Node::Recip(_) => ops.div += 1,
            Node::Sin(_) | Node::Cos(_) | Node::Sign(_) | Node::Tanh(_) => ops.trig += 1,
            Node::Var(Var::SinQ(_) | Var::CosQ(_)) => ops.trig += 1,
            Node::Const(_) | Node::Var(_) => {}
        }
    }
    ops
}
