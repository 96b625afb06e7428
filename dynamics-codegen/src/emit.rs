//! Emission: a set of graph outputs becomes one straight-line Rust function body.
//!
//! Only the nodes the outputs need are emitted, in the arena's order (children first). Nodes
//! that depend only on robot parameters are hoisted to the top, then each needed joint's sine
//! and cosine are computed once, then the rest. A node used once is written inline in its
//! user; a node used more often gets a `let tN`. `a + (−b)` is written `a − b`.

use crate::derive::Equations;
use crate::symbolic::{Graph, Node, NodeId, Var};
use proc_macro2::{Span, TokenStream};
use quote::quote;

/// Operation counts of an emitted function.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCount {
    /// Multiplications.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
    /// Negations.
    pub neg: usize,
    /// Divisions.
    pub div: usize,
    /// Sine and cosine evaluations (a `sin_cos` pair counts 2).
    pub trig: usize,
}

/// An emitted function body.
pub struct Body {
    /// The statements and the result expression.
    pub tokens: TokenStream,
    /// Its operations.
    pub ops: OpCount,
    /// The struct fields (indices into [`Equations::fields`]) it reads.
    pub fields_read: Vec<usize>,
}

impl OpCount {
    /// Multiplications, additions and negations together.
    #[must_use]
    pub fn flops(&self) -> usize {
        self.mul + self.add + self.neg + self.div
    }
}

/// The shape of a function's result.
pub enum Shape<'a> {
    /// A scalar.
    Scalar(NodeId),
    /// A vector.
    Vector(&'a [NodeId]),
    /// A matrix, rows first.
    Matrix(&'a [Vec<NodeId>]),
}

impl Shape<'_> {
    fn outputs(&self) -> Vec<NodeId> {
        match self {
            Shape::Scalar(id) => vec![*id],
            Shape::Vector(v) => v.to_vec(),
            Shape::Matrix(m) => m.iter().flatten().copied().collect(),
        }
    }
}

/// Where emitted code finds the runtime and the robot's fields.
pub struct Context<'a> {
    /// Path of the runtime crate, e.g. `::dynamics_runtime`.
    pub krate: &'a TokenStream,
    /// How to read struct field `k` (usually `self.name`).
    pub fields: Vec<TokenStream>,
}

fn local(name: &str) -> proc_macro2::Ident {
    proc_macro2::Ident::new(name, Span::mixed_site())
}

/// Emits the body of a function computing `shape` from `eq`, and counts its operations.
#[must_use]
pub fn body(eq: &Equations, shape: &Shape, ctx: &Context) -> Body {
    Emitter::new(eq, ctx).run(shape)
}

struct Emitter<'a> {
    graph: &'a Graph,
    eq: &'a Equations,
    ctx: &'a Context<'a>,
    uses: Vec<u32>,
    needed: Vec<bool>,
    bound: Vec<bool>,
    ops: OpCount,
}

impl<'a> Emitter<'a> {
    fn new(eq: &'a Equations, ctx: &'a Context<'a>) -> Emitter<'a> {
        let n = eq.graph.len();
        Emitter {
            graph: &eq.graph,
            eq,
            ctx,
            uses: vec![0; n],
            needed: vec![false; n],
            bound: vec![false; n],
            ops: OpCount::default(),
        }
    }

    /// The nodes an emitted node reads, with `a + (−b)` read as `a − b`.
    fn operands(&self, id: NodeId) -> Vec<NodeId> {
        match self.graph.node(id) {
            Node::Add(a, b) => {
                let (a, b) = self.as_sub(a, b).unwrap_or((a, b));
                vec![a, b]
            }
            Node::Mul(a, b) => vec![a, b],
            Node::Neg(a) | Node::Recip(a) | Node::Sin(a) | Node::Cos(a) => vec![a],
            Node::Var(Var::SinQ(i) | Var::CosQ(i)) => {
                self.eq.angle_offsets[usize::from(i)].into_iter().collect()
            }
            Node::Const(_) | Node::Var(_) => vec![],
        }
    }

    /// `(a, x)` if `a + b` is `a − x`.
    fn as_sub(&self, a: NodeId, b: NodeId) -> Option<(NodeId, NodeId)> {
        match (self.graph.node(a), self.graph.node(b)) {
            (_, Node::Neg(x)) => Some((a, x)),
            (Node::Neg(x), _) => Some((b, x)),
            _ => None,
        }
    }

    fn mark(&mut self, outputs: &[NodeId]) {
        let mut stack = outputs.to_vec();
        for &o in outputs {
            self.uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut self.needed[id.index()], true) {
                continue;
            }
            for c in self.operands(id) {
                self.uses[c.index()] += 1;
                stack.push(c);
            }
        }
    }

    fn is_leaf(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Var(_) | Node::Const(_))
    }

    fn leaf(&self, id: NodeId) -> TokenStream {
        let krate = self.ctx.krate;
        match self.graph.node(id) {
            Node::Const(c) if c.is_zero() => quote!(T::ZERO),
            Node::Const(c) if c.is_one() => quote!(T::ONE),
            Node::Const(c) => {
                let x = c.to_f64();
                // A literal cannot spell a non-finite value (and the literal constructor
                // panics on one); such a constant can only come from overflowing arithmetic
                // of finite parameters.
                let value = if x.is_nan() {
                    quote!(::core::f64::NAN)
                } else if x.is_infinite() && x > 0.0 {
                    quote!(::core::f64::INFINITY)
                } else if x.is_infinite() {
                    quote!(::core::f64::NEG_INFINITY)
                } else {
                    let lit = proc_macro2::Literal::f64_suffixed(x);
                    quote!(#lit)
                };
                quote!(<T as #krate::__private::Real>::from_f64(#value))
            }
            Node::Var(Var::Q(i)) => {
                let i = usize::from(i);
                let q = local("q");
                quote!(#q[#i])
            }
            Node::Var(Var::Qd(i)) => {
                let i = usize::from(i);
                let qd = local("qd");
                quote!(#qd[#i])
            }
            Node::Var(Var::Qdd(i)) => {
                let i = usize::from(i);
                let qdd = local("qdd");
                quote!(#qdd[#i])
            }
            Node::Var(Var::SinQ(i)) => {
                let s = local(&format!("s{}", i + 1));
                quote!(#s)
            }
            Node::Var(Var::CosQ(i)) => {
                let c = local(&format!("c{}", i + 1));
                quote!(#c)
            }
            Node::Var(Var::Param(k)) => {
                let p = local(&format!("p_{}", self.eq.fields[usize::from(k)]));
                quote!(#p)
            }
            _ => quote!(),
        }
    }

    /// The expression of a node: its name if bound, else written out.
    fn expr(&mut self, id: NodeId) -> TokenStream {
        if self.is_leaf(id) {
            return self.leaf(id);
        }
        if self.bound[id.index()] {
            let t = local(&format!("t{}", id.0));
            return quote!(#t);
        }
        self.define(id)
    }

    /// An operand, parenthesized when it is written out.
    fn operand(&mut self, id: NodeId) -> TokenStream {
        let e = self.expr(id);
        if self.is_leaf(id) || self.bound[id.index()] {
            e
        } else {
            quote!((#e))
        }
    }

    fn define(&mut self, id: NodeId) -> TokenStream {
        let krate = self.ctx.krate;
        match self.graph.node(id) {
            Node::Add(a, b) => {
                self.ops.add += 1;
                if let Some((a, x)) = self.as_sub(a, b) {
                    let (a, x) = (self.operand(a), self.operand(x));
                    quote!(#a - #x)
                } else {
                    let (a, b) = (self.operand(a), self.operand(b));
                    quote!(#a + #b)
                }
            }
            Node::Mul(a, b) => {
                self.ops.mul += 1;
                let (a, b) = (self.operand(a), self.operand(b));
                quote!(#a * #b)
            }
            Node::Neg(a) => {
                self.ops.neg += 1;
                let a = self.operand(a);
                quote!(-#a)
            }
            Node::Recip(a) => {
                self.ops.div += 1;
                let a = self.operand(a);
                quote!(T::ONE / #a)
            }
            Node::Sin(a) => {
                self.ops.trig += 1;
                let a = self.expr(a);
                quote!(<T as #krate::__private::Real>::sin(#a))
            }
            Node::Cos(a) => {
                self.ops.trig += 1;
                let a = self.expr(a);
                quote!(<T as #krate::__private::Real>::cos(#a))
            }
            Node::Const(_) | Node::Var(_) => self.leaf(id),
        }
    }

    fn run(mut self, shape: &Shape) -> Body {
        let krate = self.ctx.krate;
        let outputs = shape.outputs();
        self.mark(&outputs);
        // A node depends on the state if it reads q, qd or qdd.
        let n = self.graph.len();
        let mut state = vec![false; n];
        for (id, node) in self.graph.nodes() {
            state[id.index()] = match node {
                Node::Var(Var::Param(_)) | Node::Const(_) => false,
                Node::Var(_) => true,
                _ => self.operands(id).iter().any(|c| state[c.index()]),
            };
        }
        let mut prelude = Vec::new();
        let mut statements = Vec::new();
        let mut fields_read = Vec::new();
        // Parameters, read once.
        for (id, node) in self.graph.nodes() {
            if let Node::Var(Var::Param(k)) = node {
                if self.needed[id.index()] {
                    fields_read.push(usize::from(k));
                    let name = self.leaf(id);
                    let field = &self.ctx.fields[usize::from(k)];
                    prelude.push(quote!(let #name: T = #krate::__private::param::<T, _>(#field);));
                }
            }
        }
        let bind = |me: &Self, id: NodeId| {
            !me.is_leaf(id) && (me.uses[id.index()] > 1 || outputs.contains(&id))
        };
        for phase_state in [false, true] {
            if phase_state {
                // Sines and cosines of the joint angles, once each.
                for i in 0..self.eq.dof {
                    let i16 = u16::try_from(i).unwrap_or(u16::MAX);
                    let find = |v: Var| {
                        self.graph
                            .nodes()
                            .find(|(id, node)| *node == Node::Var(v) && self.needed[id.index()])
                            .map(|(id, _)| id)
                    };
                    let (s, c) = (find(Var::SinQ(i16)), find(Var::CosQ(i16)));
                    if s.is_none() && c.is_none() {
                        continue;
                    }
                    let q = local("q");
                    let angle = match self.eq.angle_offsets[i] {
                        Some(off) => {
                            let o = self.operand(off);
                            quote!(#q[#i] + #o)
                        }
                        None => quote!(#q[#i]),
                    };
                    let sn = local(&format!("s{}", i + 1));
                    let cn = local(&format!("c{}", i + 1));
                    let real = quote!(<T as #krate::__private::Real>);
                    statements.push(match (s, c) {
                        (Some(_), Some(_)) => {
                            self.ops.trig += 2;
                            quote!(let (#sn, #cn) = #real::sin_cos(#angle);)
                        }
                        (Some(_), None) => {
                            self.ops.trig += 1;
                            quote!(let #sn = #real::sin(#angle);)
                        }
                        _ => {
                            self.ops.trig += 1;
                            quote!(let #cn = #real::cos(#angle);)
                        }
                    });
                }
            }
            for (id, _) in self.graph.nodes() {
                let i = id.index();
                if !self.needed[i] || state[i] != phase_state || !bind(&self, id) {
                    continue;
                }
                let e = self.define(id);
                self.bound[i] = true;
                let t = local(&format!("t{}", id.0));
                let line = quote!(let #t = #e;);
                if phase_state {
                    statements.push(line);
                } else {
                    prelude.push(line);
                }
            }
        }
        let result = match shape {
            Shape::Scalar(id) => self.expr(*id),
            Shape::Vector(v) => {
                let items: Vec<TokenStream> = v.iter().map(|&id| self.expr(id)).collect();
                quote!([#(#items),*])
            }
            Shape::Matrix(m) => {
                let rows: Vec<TokenStream> = m
                    .iter()
                    .map(|r| {
                        let items: Vec<TokenStream> = r.iter().map(|&id| self.expr(id)).collect();
                        quote!([#(#items),*])
                    })
                    .collect();
                quote!([#(#rows),*])
            }
        };
        Body {
            tokens: quote!(#(#prelude)* #(#statements)* #result),
            ops: self.ops,
            fields_read,
        }
    }
}
