//! Operation counting: the multiplications, additions, negations, divisions and sines and
//! cosines of an emitted function once inlined, and its depth, the longest chain of dependent
//! operations from the inputs to a result.

use super::parts::OpCount;
use super::plan::operands;
use super::sums::Sums;
use crate::symbolic::{Graph, Node, NodeId, Var};
use crate::trace::Equations;
use std::cell::Cell;

/// Operation counts of the code computing `outputs`, shared parts included: what a function
/// costs once the compiler has inlined the configuration and dropped what it does not read.
#[must_use]
pub fn count(eq: &Equations, outputs: &[NodeId]) -> OpCount {
    let e = Marked::new(eq, outputs);
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

/// What the code of some outputs computes, as an emitter without names marks it (every node
/// computed where it is read, nothing read from a shared function): the nodes needed, how
/// often each is read, and the depths once asked for. Only what counting needs, without an
/// emitter's names.
struct Marked<'a> {
    graph: &'a Graph,
    uses: Vec<u32>,
    needed: Vec<bool>,
    depth: Vec<Cell<u32>>,
}

impl<'a> Marked<'a> {
    fn new(eq: &'a Equations, outputs: &[NodeId]) -> Marked<'a> {
        let n = eq.graph.len();
        let mut uses = vec![0; n];
        let mut needed = vec![false; n];
        let mut stack = outputs.to_vec();
        for &o in outputs {
            uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut needed[id.index()], true) {
                continue;
            }
            for c in operands(eq, id) {
                uses[c.index()] += 1;
                stack.push(c);
            }
        }
        Marked {
            graph: &eq.graph,
            uses,
            needed,
            depth: vec![Cell::new(u32::MAX); n],
        }
    }
}

impl Sums for Marked<'_> {
    fn graph(&self) -> &Graph {
        self.graph
    }

    fn in_place(&self, c: NodeId) -> bool {
        self.uses[c.index()] <= 1
    }

    fn depths(&self) -> &[Cell<u32>] {
        &self.depth
    }
}
