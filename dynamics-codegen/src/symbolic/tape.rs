//! A tape: the nodes that some outputs of a [`Graph`] need, in the graph's order (children
//! before parents), as a flat list of instructions over numbered slots, evaluated in `f64`
//! into a buffer that the caller keeps and reuses.
//!
//! [`Graph::eval`] computes every node of the graph; a robot's graph holds every output ever
//! traced (M, C, the kinematics, the forward dynamics, …), so evaluating one family at many
//! states (the regressor at every sample of a measured trajectory) would pay for all of them.
//! The tape keeps only the nodes reachable from its outputs ([`Graph::live`]).
//!
//! Slots: the leaves first (one per distinct [`Var`] the outputs reach, whose values the caller
//! gives in the order of [`Tape::leaves`]), then the constants, then one slot per operation.
//! The arithmetic is [`Graph::eval`]'s, operation for operation, so both give the same bits in
//! `f64`; [`Tape::eval_in`] runs it on any [`TapeScalar`] (several samples in vector lanes).

use super::graph::Graph;
use super::node::{Node, NodeId, Var};
use std::ops::{Add, Mul, Neg};

/// What a tape computes with: `f64`, or a type of several `f64` lanes (the command line's).
pub trait TapeScalar: Copy + Add<Output = Self> + Mul<Output = Self> + Neg<Output = Self> {
    /// Every lane `x`.
    fn splat(x: f64) -> Self;
    /// `1 / self`.
    #[must_use]
    fn recip(self) -> Self;
    /// The sine.
    #[must_use]
    fn sin(self) -> Self;
    /// The cosine.
    #[must_use]
    fn cos(self) -> Self;
    /// 1, −1, or 0 for a zero (as the generated code's `Real::sign`).
    #[must_use]
    fn sign(self) -> Self;
    /// The hyperbolic tangent.
    #[must_use]
    fn tanh(self) -> Self;
}

impl TapeScalar for f64 {
    fn splat(x: f64) -> f64 {
        x
    }
    fn recip(self) -> f64 {
        1.0 / self
    }
    fn sin(self) -> f64 {
        f64::sin(self)
    }
    fn cos(self) -> f64 {
        f64::cos(self)
    }
    fn sign(self) -> f64 {
        if self == 0.0 {
            0.0
        } else {
            self.signum()
        }
    }
    fn tanh(self) -> f64 {
        f64::tanh(self)
    }
}

/// One operation on earlier slots.
#[derive(Clone, Copy, Debug)]
enum Op {
    Add(u32, u32),
    Mul(u32, u32),
    Neg(u32),
    Recip(u32),
    Sin(u32),
    Cos(u32),
    Sign(u32),
    Tanh(u32),
}

/// The straight-line evaluation of some outputs of a graph.
#[derive(Clone, Debug)]
pub struct Tape {
    leaves: Vec<Var>,
    constants: Vec<f64>,
    ops: Vec<Op>,
    outputs: Vec<u32>,
}

impl Tape {
    /// The tape of `outputs` (node ids into `graph`).
    #[must_use]
    pub fn new(graph: &Graph, outputs: &[NodeId]) -> Tape {
        let live = graph.live(outputs);
        let mut leaves = Vec::new();
        let mut constants = Vec::new();
        let mut operations: Vec<(NodeId, Node)> = Vec::new();
        // The slot of each live node, by kind first: the final slot is known once the counts
        // of leaves and constants are.
        let mut place: Vec<Slot> = vec![Slot::Dead; graph.len()];
        for (id, node) in graph.nodes().filter(|(id, _)| live[id.index()]) {
            place[id.index()] = match node {
                Node::Var(v) => {
                    leaves.push(v);
                    Slot::Leaf(leaves.len() - 1)
                }
                Node::Const(c) => {
                    constants.push(c.to_f64());
                    Slot::Constant(constants.len() - 1)
                }
                _ => {
                    operations.push((id, node));
                    Slot::Op(operations.len() - 1)
                }
            };
        }
        let (l, c) = (leaves.len(), constants.len());
        let slot = |id: NodeId| -> u32 {
            let index = match place[id.index()] {
                Slot::Leaf(k) => k,
                Slot::Constant(k) => l + k,
                Slot::Op(k) => l + c + k,
                Slot::Dead => unreachable!("an operand of a live node is live"),
            };
            u32::try_from(index).expect("a tape exceeds u32 slots")
        };
        let ops = operations
            .iter()
            .map(|&(_, node)| op(node, &slot))
            .collect();
        Tape {
            outputs: outputs.iter().map(|&id| slot(id)).collect(),
            leaves,
            constants,
            ops,
        }
    }

    /// The inputs the outputs depend on, in the order [`Tape::eval`] takes their values.
    #[must_use]
    pub fn leaves(&self) -> &[Var] {
        &self.leaves
    }

    /// The number of operations evaluated per call.
    #[must_use]
    pub fn operations(&self) -> usize {
        self.ops.len()
    }

    /// Evaluates the outputs, `leaves[k]` being the value of `self.leaves()[k]`, into `outputs`
    /// (one per output node), with `work` as scratch (kept between calls to save allocations).
    ///
    /// # Panics
    /// If `leaves` or `outputs` is shorter than the tape's.
    pub fn eval(&self, leaves: &[f64], work: &mut Vec<f64>, outputs: &mut [f64]) {
        self.eval_in(leaves, work, outputs);
    }

    /// [`Tape::eval`] on any [`TapeScalar`].
    ///
    /// # Panics
    /// If `leaves` or `outputs` is shorter than the tape's.
    pub fn eval_in<S: TapeScalar>(&self, leaves: &[S], work: &mut Vec<S>, outputs: &mut [S]) {
        let l = self.leaves.len();
        work.clear();
        work.extend_from_slice(&leaves[..l]);
        work.extend(self.constants.iter().map(|&c| S::splat(c)));
        work.reserve(self.ops.len());
        for op in &self.ops {
            let at = |k: u32| work[k as usize];
            let v = match *op {
                Op::Add(a, b) => at(a) + at(b),
                Op::Mul(a, b) => at(a) * at(b),
                Op::Neg(a) => -at(a),
                Op::Recip(a) => at(a).recip(),
                Op::Sin(a) => at(a).sin(),
                Op::Cos(a) => at(a).cos(),
                Op::Sign(a) => at(a).sign(),
                Op::Tanh(a) => at(a).tanh(),
            };
            work.push(v);
        }
        for (out, &k) in outputs.iter_mut().zip(&self.outputs) {
            *out = work[k as usize];
        }
    }
}

/// Where a node of the graph goes on the tape, by kind.
#[derive(Clone, Copy)]
enum Slot {
    Dead,
    Leaf(usize),
    Constant(usize),
    Op(usize),
}

/// The operation of `node`, its operands given by their slots.
fn op(node: Node, slot: &impl Fn(NodeId) -> u32) -> Op {
    match node {
        Node::Add(a, b) => Op::Add(slot(a), slot(b)),
        Node::Mul(a, b) => Op::Mul(slot(a), slot(b)),
        Node::Neg(a) => Op::Neg(slot(a)),
        Node::Recip(a) => Op::Recip(slot(a)),
        Node::Sin(a) => Op::Sin(slot(a)),
        Node::Cos(a) => Op::Cos(slot(a)),
        Node::Sign(a) => Op::Sign(slot(a)),
        Node::Tanh(a) => Op::Tanh(slot(a)),
        Node::Const(_) | Node::Var(_) => {
            unreachable!("leaves and constants have slots of their own")
        }
    }
}
