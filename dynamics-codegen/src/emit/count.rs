//! Operation counting: the multiplications, additions, negations, divisions and sines and
//! cosines of an emitted function once inlined, and its depth, the longest chain of dependent
//! operations from the inputs to a result.

use super::emitter::Emitter;
use super::parts::OpCount;
use super::sum_order::sum_order;
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

impl Emitter<'_> {
    /// The number of dependent operations from the inputs to node `id` as emitted, each sum
    /// added in [`sum_order`]. A fused multiply-add counts as its two operations, as in the
    /// flop counts; a negation folds into what reads it.
    pub(super) fn depth(&mut self, id: NodeId) -> u32 {
        if self.depth[id.index()] != u32::MAX {
            return self.depth[id.index()];
        }
        let d = match self.graph.node(id) {
            Node::Add(..) => {
                let (_, depths) = self.sum_terms_with_depth(id);
                sum_order(&depths).1
            }
            Node::Mul(a, b) => 1 + self.depth(a).max(self.depth(b)),
            Node::Recip(a) | Node::Sin(a) | Node::Cos(a) | Node::Sign(a) | Node::Tanh(a) => {
                1 + self.depth(a)
            }
            Node::Neg(a) => self.depth(a),
            Node::Const(_) | Node::Var(_) => 0,
        };
        self.depth[id.index()] = d;
        d
    }
}
