//! Reading the graph: numeric evaluation, the live set of a set of outputs, and forward-mode
//! partial derivatives with respect to a joint position (`∂ sin q_j/∂q_j = cos q_j`).

use super::graph::Graph;
use super::node::{Node, NodeId, Var};
use super::number::Number;

impl Graph {
    /// Evaluates every node in order, reading inputs from `input`.
    pub fn eval(&self, mut input: impl FnMut(Var) -> f64) -> Vec<f64> {
        let mut values: Vec<f64> = Vec::with_capacity(self.nodes.len());
        for node in &self.nodes {
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
        let mut live = vec![false; self.nodes.len()];
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
        let end = outputs.iter().map(|o| o.index() + 1).max().unwrap_or(0);
        let live = self.live(outputs);
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
                Node::Var(v) => match v {
                    Var::Q(j) if j == joint => one,
                    Var::SinQ(j) if j == joint => self.var(Var::CosQ(j)),
                    Var::CosQ(j) if j == joint => {
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
}

#[cfg(test)]
mod tests {
    use super::Graph;
    use crate::symbolic::Var;

    #[test]
    fn derivative_of_trigonometric_leaves() {
        let mut g = Graph::new();
        let s = g.var(Var::SinQ(0));
        let c = g.var(Var::CosQ(0));
        let sc = g.mul(s, c);
        let d = g.derivative(&[sc], 0)[0];
        let values = g.eval(|v| match v {
            Var::SinQ(_) => 0.3f64.sin(),
            Var::CosQ(_) => 0.3f64.cos(),
            _ => 0.0,
        });
        assert!((values[d.index()] - (2.0 * 0.3f64).cos()).abs() < 1e-15);
        let independent = g.derivative(&[sc], 1)[0];
        assert!(g.is_zero(independent));
    }
}
