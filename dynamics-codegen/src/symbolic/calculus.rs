//! Reading the graph: numeric evaluation, the live set of a set of outputs, forward-mode
//! partial derivatives with respect to a joint position (`∂ sin q_j/∂q_j = cos q_j`) or
//! velocity, and the substitution of leaves by other nodes.

use super::graph::Graph;
use super::node::{Node, NodeId, Var};
use super::number::Number;

impl Graph {
    /// Evaluates every node in order, reading inputs from `input`.
    pub fn eval(&self, input: impl FnMut(Var) -> f64) -> Vec<f64> {
        self.eval_below(self.nodes.len(), input)
    }

    /// Evaluates the first `end` nodes in order (the values of `outputs` need those before the
    /// last of them), reading inputs from `input`.
    pub fn eval_below(&self, end: usize, input: impl FnMut(Var) -> f64) -> Vec<f64> {
        self.eval_marked(&vec![true; end], input)
    }

    /// Evaluates the nodes marked in `live` (as [`Graph::live`] marks them: every operand of
    /// a marked node marked), in order; the others are left 0 (nothing marked reads them).
    /// Evaluating one family's outputs many times, the rest of the graph is skipped.
    pub fn eval_marked(&self, live: &[bool], mut input: impl FnMut(Var) -> f64) -> Vec<f64> {
        let end = live.len().min(self.nodes.len());
        let mut values: Vec<f64> = Vec::with_capacity(end);
        for (node, &live) in self.nodes[..end].iter().zip(live) {
            if !live {
                values.push(0.0);
                continue;
            }
            let v = match *node {
                Node::Const(c) => c.to_f64(),
                Node::Var(v) => input(v),
                Node::Add(a, b) => values[a.index()] + values[b.index()],
                Node::Mul(a, b) => values[a.index()] * values[b.index()],
                Node::Neg(a) => -values[a.index()],
                Node::Recip(a) => 1.0 / values[a.index()],
                Node::Sin(a) => values[a.index()].sin(),
                Node::Cos(a) => values[a.index()].cos(),
                Node::Sign(a) => {
                    let x = values[a.index()];
                    if x == 0.0 {
                        0.0
                    } else {
                        x.signum()
                    }
                }
                Node::Tanh(a) => values[a.index()].tanh(),
            };
            values.push(v);
        }
        values
    }

    /// Marks the nodes that `outputs` depend on.
    #[must_use]
    pub fn live(&self, outputs: &[NodeId]) -> Vec<bool> {
        let mut live = self.live_below(outputs);
        live.resize(self.nodes.len(), false);
        live
    }

    /// [`Graph::live`] up to the last of `outputs` (an operand comes before what reads it):
    /// what a walk up to there reads, without clearing the rest of the graph.
    fn live_below(&self, outputs: &[NodeId]) -> Vec<bool> {
        let end = outputs.iter().map(|o| o.index() + 1).max().unwrap_or(0);
        let mut live = vec![false; end];
        let mut stack: Vec<NodeId> = outputs.to_vec();
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut live[id.index()], true) {
                continue;
            }
            stack.extend(self.node(id).operands());
        }
        live
    }

    /// Partial derivatives of `outputs` with respect to joint position `q_j`, by forward
    /// differentiation of the graph: `∂ sin(q_j)/∂q_j = cos(q_j)`, `∂ cos(q_j)/∂q_j = −sin(q_j)`,
    /// `∂q_j/∂q_j = 1`. Returns one node per output (a constant zero where independent).
    pub fn derivative(&mut self, outputs: &[NodeId], joint: u16) -> Vec<NodeId> {
        self.derivative_by(outputs, Wrt::Position(joint))
    }

    /// Partial derivatives of `outputs` with respect to the joint variable `wrt`, one node
    /// per output, by forward differentiation of the graph.
    pub fn derivative_by(&mut self, outputs: &[NodeId], wrt: Wrt) -> Vec<NodeId> {
        let end = outputs.iter().map(|o| o.index() + 1).max().unwrap_or(0);
        let live = self.live_below(outputs);
        let zero = self.num(Number::ZERO);
        let one = self.num(Number::ONE);
        let mut d: Vec<NodeId> = vec![zero; end];
        for i in 0..end {
            if !live[i] {
                continue;
            }
            let id = NodeId(u32::try_from(i).expect("graph exceeds u32 nodes"));
            d[i] = match self.node(id) {
                Node::Const(_) => zero,
                Node::Var(v) => match (v, wrt) {
                    (Var::Q(j), Wrt::Position(k)) | (Var::Qd(j), Wrt::Velocity(k)) if j == k => one,
                    (Var::SinQ(j), Wrt::Position(k)) if j == k => self.var(Var::CosQ(j)),
                    (Var::CosQ(j), Wrt::Position(k)) if j == k => {
                        let s = self.var(Var::SinQ(j));
                        self.neg(s)
                    }
                    _ => zero,
                },
                Node::Add(a, b) => self.add(d[a.index()], d[b.index()]),
                Node::Mul(a, b) => {
                    let l = self.mul(d[a.index()], b);
                    let r = self.mul(a, d[b.index()]);
                    self.add(l, r)
                }
                Node::Neg(a) => self.neg(d[a.index()]),
                Node::Recip(a) => {
                    // d(1/a) = −da / a²
                    let aa = self.mul(id, id);
                    let t = self.mul(d[a.index()], aa);
                    self.neg(t)
                }
                Node::Sin(a) => {
                    let c = self.cos(a);
                    self.mul(c, d[a.index()])
                }
                Node::Cos(a) => {
                    let s = self.sin(a);
                    let t = self.mul(s, d[a.index()]);
                    self.neg(t)
                }
                // Flat away from 0, where friction's sign is not differentiated.
                Node::Sign(_) => zero,
                Node::Tanh(a) => {
                    // d tanh a = (1 − tanh² a) da
                    let square = self.mul(id, id);
                    let minus = self.neg(square);
                    let slope = self.add(one, minus);
                    self.mul(slope, d[a.index()])
                }
            };
        }
        outputs.iter().map(|o| d[o.index()]).collect()
    }

    /// `outputs` with each leaf `v` for which `leaf(v)` is `Some(x)` replaced by node `x`:
    /// the nodes on the way are built anew (simplified as ever), the others kept.
    pub fn substitute(
        &mut self,
        outputs: &[NodeId],
        leaf: impl Fn(Var) -> Option<NodeId>,
    ) -> Vec<NodeId> {
        let live = self.live_below(outputs);
        let nodes = live.iter().enumerate().filter(|(_, &l)| l).map(|(i, _)| i);
        self.substitute_at(outputs, nodes, leaf)
    }

    /// The live nodes of `outputs` that depend on a leaf `varies` picks, in the arena's order:
    /// the only ones a substitution of those leaves can change, found once for many
    /// substitutions ([`Graph::substitute_within`]).
    #[must_use]
    pub fn dependents(&self, outputs: &[NodeId], varies: impl Fn(Var) -> bool) -> Vec<NodeId> {
        let live = self.live_below(outputs);
        let mut depends = vec![false; live.len()];
        let mut found = Vec::new();
        for (i, _) in live.iter().enumerate().filter(|(_, &l)| l) {
            let id = NodeId(u32::try_from(i).expect("graph exceeds u32 nodes"));
            let node = self.node(id);
            depends[i] = match node {
                Node::Var(v) => varies(v),
                _ => node.operands().any(|a| depends[a.index()]),
            };
            if depends[i] {
                found.push(id);
            }
        }
        found
    }

    /// [`Graph::substitute`] of leaves that only `nodes`, the [`Graph::dependents`] of
    /// `outputs` on every leaf `leaf` replaces, depend on: the same nodes built in the same
    /// order, without a walk of the others.
    pub fn substitute_within(
        &mut self,
        outputs: &[NodeId],
        nodes: &[NodeId],
        leaf: impl Fn(Var) -> Option<NodeId>,
    ) -> Vec<NodeId> {
        self.substitute_at(outputs, nodes.iter().map(|id| id.index()), leaf)
    }

    /// The substitution's walk over `nodes`, by index in increasing order, every node that
    /// can change among them.
    fn substitute_at(
        &mut self,
        outputs: &[NodeId],
        nodes: impl Iterator<Item = usize>,
        leaf: impl Fn(Var) -> Option<NodeId>,
    ) -> Vec<NodeId> {
        let end = outputs.iter().map(|o| o.index() + 1).max().unwrap_or(0);
        let mut new: Vec<NodeId> = (0..end)
            .map(|i| NodeId(u32::try_from(i).expect("graph exceeds u32 nodes")))
            .collect();
        for i in nodes {
            let id = new[i];
            let node = self.node(id);
            let changed = node.operands().any(|a| new[a.index()] != a);
            new[i] = match node {
                Node::Var(v) => leaf(v).unwrap_or(id),
                _ if !changed => id,
                Node::Add(a, b) => self.add(new[a.index()], new[b.index()]),
                Node::Mul(a, b) => self.mul(new[a.index()], new[b.index()]),
                Node::Neg(a) => self.neg(new[a.index()]),
                // A reciprocal of zero stays a division by zero, as before the substitution.
                Node::Recip(a) => {
                    let a = new[a.index()];
                    self.recip(a).unwrap_or_else(|| self.intern_recip(a))
                }
                Node::Sin(a) => self.sin(new[a.index()]),
                Node::Cos(a) => self.cos(new[a.index()]),
                Node::Sign(a) => self.sign(new[a.index()]),
                Node::Tanh(a) => self.tanh(new[a.index()]),
                Node::Const(_) => id,
            };
        }
        outputs.iter().map(|o| new[o.index()]).collect()
    }
}

/// The joint variable a derivative is taken by: position `q_j` or velocity `q̇_j` (from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrt {
    /// `q_j`.
    Position(u16),
    /// `q̇_j`.
    Velocity(u16),
}
