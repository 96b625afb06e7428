//! A hash-consed expression graph.
//!
//! Nodes live in one arena, children before parents, addressed by [`NodeId`]. Every
//! constructor looks its node up first, so a subexpression built twice is stored once: common
//! subexpressions are shared as they are built. Constructors also apply cheap local rules
//! (constant folding, `x·0`, `x·1`, `x + 0`, `−(−x)`, `c₁·(c₂·x)`, `a·x + b·x`), so a traced
//! algorithm comes out already customized to its robot: every zero, one and exact constant of
//! the D-H table folded away.

use super::hasher::FxHashMap;
use super::node::{Node, NodeId, Var};
use super::number::Number;
use std::ops::{Add, Mul, Neg};

/// Counters of the graph's construction, for tests and benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Nodes stored.
    pub nodes: usize,
    /// Constructions answered by an existing node.
    pub shared: usize,
    /// Constructions answered by a simplification rule.
    pub simplified: usize,
}

/// The expression arena.
#[derive(Clone, Debug, Default)]
pub struct Graph {
    pub(super) nodes: Vec<Node>,
    // Only looked up, never iterated: emission order is the arena's order.
    memo: FxHashMap<Node, NodeId>,
    /// The inputs and constants, in the arena's order: what the emitters look for at the top
    /// of every function, without a walk of the whole arena.
    leaves: Vec<NodeId>,
    stats: Stats,
}

impl Graph {
    /// An empty graph.
    #[must_use]
    pub fn new() -> Graph {
        Graph::default()
    }

    /// The node behind an id.
    #[must_use]
    pub fn node(&self, id: NodeId) -> Node {
        self.nodes[id.index()]
    }

    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the graph is empty.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Construction counters.
    #[must_use]
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// All nodes, children before parents.
    pub fn nodes(&self) -> impl Iterator<Item = (NodeId, Node)> + '_ {
        self.nodes.iter().enumerate().map(|(i, n)| {
            (
                NodeId(u32::try_from(i).expect("graph exceeds u32 nodes")),
                *n,
            )
        })
    }

    /// The inputs and constants with their ids, in the arena's order.
    pub fn leaves(&self) -> impl Iterator<Item = (NodeId, Node)> + '_ {
        self.leaves.iter().map(|&id| (id, self.node(id)))
    }

    /// The node's id, if the graph has it.
    #[must_use]
    pub fn lookup(&self, node: Node) -> Option<NodeId> {
        self.memo.get(&node).copied()
    }

    fn intern(&mut self, node: Node) -> NodeId {
        if let Some(&id) = self.memo.get(&node) {
            self.stats.shared += 1;
            return id;
        }
        let id = NodeId(u32::try_from(self.nodes.len()).expect("graph exceeds u32 nodes"));
        self.nodes.push(node);
        self.memo.insert(node, id);
        if matches!(node, Node::Var(_) | Node::Const(_)) {
            self.leaves.push(id);
        }
        self.stats.nodes += 1;
        id
    }

    fn simplified(&mut self, id: NodeId) -> NodeId {
        self.stats.simplified += 1;
        id
    }

    /// The constant, if `id` is one.
    #[must_use]
    pub fn constant(&self, id: NodeId) -> Option<Number> {
        match self.node(id) {
            Node::Const(c) => Some(c),
            _ => None,
        }
    }

    /// Whether `id` is the constant zero.
    #[must_use]
    pub fn is_zero(&self, id: NodeId) -> bool {
        self.constant(id).is_some_and(Number::is_zero)
    }

    /// A constant node.
    pub fn num(&mut self, c: Number) -> NodeId {
        self.intern(Node::Const(c))
    }

    /// An input node.
    pub fn var(&mut self, v: Var) -> NodeId {
        self.intern(Node::Var(v))
    }

    /// Splits `c·x` into `(c, x)`, `−x` into `(−1, x)` and `x` into `(1, x)`.
    fn coefficient(&self, id: NodeId) -> (Number, NodeId) {
        match self.node(id) {
            Node::Mul(a, b) => match self.node(a) {
                Node::Const(c) => (c, b),
                _ => (Number::ONE, id),
            },
            Node::Neg(a) => (Number::MINUS_ONE, a),
            _ => (Number::ONE, id),
        }
    }

    /// `a + b`.
    pub fn add(&mut self, a: NodeId, b: NodeId) -> NodeId {
        match (self.node(a), self.node(b)) {
            (Node::Const(x), Node::Const(y)) => {
                let c = self.num(x.add(y));
                return self.simplified(c);
            }
            (Node::Const(x), _) if x.is_zero() => return self.simplified(b),
            (_, Node::Const(y)) if y.is_zero() => return self.simplified(a),
            _ => {}
        }
        // x + (y − x) = y and x − (x + y) = −y: terms that cancel one level down.
        if let Some(r) = self.cancel(a, b).or_else(|| self.cancel(b, a)) {
            return self.simplified(r);
        }
        let (ca, ta) = self.coefficient(a);
        let (cb, tb) = self.coefficient(b);
        if ta == tb {
            let c = self.num(ca.add(cb));
            let sum = self.mul(c, ta);
            return self.simplified(sum);
        }
        // c·x + c·y = c·(x + y) and c·x − c·y = c·(x − y): one multiplication fewer.
        if !ca.is_one() && !ca.is_minus_one() && (ca == cb || ca == cb.neg()) {
            let y = if ca == cb { tb } else { self.neg(tb) };
            let sum = self.add(ta, y);
            let c = self.num(ca);
            let r = self.mul(c, sum);
            return self.simplified(r);
        }
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Add(a, b))
    }

    /// `a + b` without a new node when `a` cancels a term of the sum `b`: `a + (−a + y) = y`,
    /// and `a + (−(a + y)) = −y`.
    fn cancel(&mut self, a: NodeId, b: NodeId) -> Option<NodeId> {
        let (ca, ta) = self.coefficient(a);
        let (cb, tb) = self.coefficient(b);
        let Node::Add(x, y) = self.node(tb) else {
            return None;
        };
        let is = |g: &Graph, t: NodeId, c: Number| g.coefficient(t) == (c, ta);
        if cb.is_one() {
            // a + (x + y) with x = −a
            if is(self, x, ca.neg()) {
                return Some(y);
            }
            if is(self, y, ca.neg()) {
                return Some(x);
            }
        } else if cb.is_minus_one() {
            // a − (x + y) with x = a
            if is(self, x, ca) {
                return Some(self.neg(y));
            }
            if is(self, y, ca) {
                return Some(self.neg(x));
            }
        }
        None
    }

    /// `a − b`.
    pub fn sub(&mut self, a: NodeId, b: NodeId) -> NodeId {
        let nb = self.neg(b);
        self.add(a, nb)
    }

    /// `a · b`.
    pub fn mul(&mut self, a: NodeId, b: NodeId) -> NodeId {
        let (a, b) = match (self.node(a), self.node(b)) {
            (Node::Const(x), Node::Const(y)) => {
                let c = self.num(x.mul(y));
                return self.simplified(c);
            }
            (_, Node::Const(_)) => (b, a),
            _ => (a, b),
        };
        if let Node::Const(c) = self.node(a) {
            if c.is_zero() {
                return self.simplified(a);
            }
            if c.is_one() {
                return self.simplified(b);
            }
            if c.is_minus_one() {
                let n = self.neg(b);
                return self.simplified(n);
            }
            // c·(d·x) = (cd)·x and c·(−x) = (−c)·x
            let (d, x) = self.coefficient(b);
            if x != b {
                let cd = self.num(c.mul(d));
                let r = self.mul(cd, x);
                return self.simplified(r);
            }
            return self.intern(Node::Mul(a, b));
        }
        // Pull constants and signs out of products: (c·x)·y = c·(x·y).
        let (ca, xa) = self.coefficient(a);
        let (cb, xb) = self.coefficient(b);
        if xa != a || xb != b {
            let c = self.num(ca.mul(cb));
            let xy = self.mul(xa, xb);
            let r = self.mul(c, xy);
            return self.simplified(r);
        }
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Mul(a, b))
    }

    /// `−a`.
    pub fn neg(&mut self, a: NodeId) -> NodeId {
        match self.node(a) {
            Node::Const(c) => {
                let r = self.num(c.neg());
                self.simplified(r)
            }
            Node::Neg(x) => self.simplified(x),
            Node::Mul(c, x) if self.constant(c).is_some() => {
                let nc = self.num(self.constant(c).unwrap_or(Number::ONE).neg());
                let r = self.mul(nc, x);
                self.simplified(r)
            }
            _ => self.intern(Node::Neg(a)),
        }
    }

    /// `1 / a`. A constant zero has no reciprocal: the result is then `None`.
    pub fn recip(&mut self, a: NodeId) -> Option<NodeId> {
        match self.node(a) {
            Node::Const(c) => {
                let r = c.recip()?;
                Some(self.num(r))
            }
            Node::Recip(x) => Some(x),
            _ => Some(self.intern(Node::Recip(a))),
        }
    }

    /// The node `1 / a` as it stands, unsimplified (a reciprocal of zero kept as written).
    pub(super) fn intern_recip(&mut self, a: NodeId) -> NodeId {
        self.intern(Node::Recip(a))
    }

    /// `sin a`.
    pub fn sin(&mut self, a: NodeId) -> NodeId {
        match self.node(a) {
            Node::Const(c) if c.is_zero() => a,
            Node::Const(c) => self.num(Number::from_float(c.to_f64().sin())),
            _ => self.intern(Node::Sin(a)),
        }
    }

    /// `sign a`, with `sign 0 = 0`; exact for a constant.
    pub fn sign(&mut self, a: NodeId) -> NodeId {
        match self.node(a) {
            Node::Const(c) if c.is_zero() => a,
            Node::Const(c) if c.is_negative() => self.num(Number::MINUS_ONE),
            Node::Const(_) => self.num(Number::ONE),
            _ => self.intern(Node::Sign(a)),
        }
    }

    /// `tanh a`.
    pub fn tanh(&mut self, a: NodeId) -> NodeId {
        match self.node(a) {
            Node::Const(c) if c.is_zero() => a,
            Node::Const(c) => self.num(Number::from_float(c.to_f64().tanh())),
            _ => self.intern(Node::Tanh(a)),
        }
    }

    /// `cos a`.
    pub fn cos(&mut self, a: NodeId) -> NodeId {
        match self.node(a) {
            Node::Const(c) if c.is_zero() => self.num(Number::ONE),
            Node::Const(c) => self.num(Number::from_float(c.to_f64().cos())),
            _ => self.intern(Node::Cos(a)),
        }
    }
}
