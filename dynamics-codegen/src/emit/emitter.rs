//! The emitter's state for one function: which nodes it needs and how often each is read,
//! what each is read as, and which shared function computes it.

use super::names::local;
use super::parts::{Context, Shared};
use super::sums::Sums;
use crate::symbolic::{Graph, Node, NodeId, Var};
use crate::trace::Equations;
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;
use std::cell::Cell;

/// Where a node read by a function is computed.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Origin {
    /// In the function itself.
    Here,
    /// In the configuration.
    Configuration,
    /// In the motion.
    Motion,
}

/// Writes one function (or only counts its operations, without a [`Context`]).
pub(super) struct Emitter<'a> {
    pub(super) graph: &'a Graph,
    pub(super) eq: &'a Equations,
    pub(super) ctx: Option<&'a Context>,
    /// How many times each node is read by the needed nodes (outputs count once).
    pub(super) uses: Vec<u32>,
    /// Whether each node is computed by (or read from the shared functions by) this function.
    pub(super) needed: Vec<bool>,
    /// What each bound node (and each constant) is read as: a local, or a field of the
    /// configuration.
    pub(super) names: Vec<Option<Ident>>,
    /// Nodes computed elsewhere (the configuration's and the motion's fields): marking stops there.
    pub(super) stop: Vec<bool>,
    /// Which shared function computes a stop node.
    pub(super) origin: Vec<Origin>,
    pub(super) temporaries: usize,
    /// `t` in a method, `u` in the configuration and `v` in the motion, whose fields a method
    /// binds as locals too.
    pub(super) temporary_prefix: &'static str,
    /// Whether there is a configuration function (the motion function takes its result).
    pub(super) has_configuration: bool,
    /// Each node's number of dependent operations as emitted ([`Sums::depth`]), once
    /// asked for (`u32::MAX` before).
    pub(super) depth: Vec<Cell<u32>>,
}

impl<'a> Emitter<'a> {
    pub(super) fn new(eq: &'a Equations, ctx: Option<&'a Context>) -> Emitter<'a> {
        let n = eq.graph.len();
        Emitter {
            graph: &eq.graph,
            eq,
            ctx,
            uses: vec![0; n],
            needed: vec![false; n],
            names: vec![None; n],
            stop: vec![false; n],
            origin: vec![Origin::Here; n],
            temporaries: 0,
            temporary_prefix: "t",
            has_configuration: false,
            depth: vec![Cell::new(u32::MAX); n],
        }
    }

    /// Reads the nodes `computed` from the fields of `shared` (by `origin`): by name, without
    /// computing them.
    pub(super) fn read_from(&mut self, computed: &[NodeId], shared: &Shared, origin: Origin) {
        for (&id, field) in computed.iter().zip(&shared.fields) {
            let mut local = field.clone();
            local.set_span(Span::mixed_site());
            self.names[id.index()] = Some(local);
            self.stop[id.index()] = true;
            self.origin[id.index()] = origin;
        }
    }

    /// The nodes an emitted node reads, with `a + (−b)` read as `a − b`.
    pub(super) fn operands(&self, id: NodeId) -> Vec<NodeId> {
        match self.graph.node(id) {
            Node::Add(a, b) => {
                let (a, b) = self.as_sub(a, b).unwrap_or((a, b));
                vec![a, b]
            }
            Node::Mul(a, b) => vec![a, b],
            Node::Neg(a)
            | Node::Recip(a)
            | Node::Sin(a)
            | Node::Cos(a)
            | Node::Sign(a)
            | Node::Tanh(a) => vec![a],
            Node::Var(Var::SinQ(i) | Var::CosQ(i)) => {
                self.eq.angle_offsets[usize::from(i)].into_iter().collect()
            }
            Node::Const(_) | Node::Var(_) => vec![],
        }
    }

    pub(super) fn mark(&mut self, outputs: &[NodeId]) {
        let mut stack = outputs.to_vec();
        for &o in outputs {
            self.uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut self.needed[id.index()], true) || self.stop[id.index()] {
                continue;
            }
            for c in self.operands(id) {
                self.uses[c.index()] += 1;
                stack.push(c);
            }
        }
    }

    pub(super) fn is_leaf(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Var(_) | Node::Const(_))
    }

    /// A constant other than 0 and 1, which gets its own `let kN`.
    pub(super) fn is_named_constant(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Const(c) if !c.is_zero() && !c.is_one())
    }

    /// What node `id` is read as, if it is read by name: its binding, or a joint variable,
    /// sine, cosine or parameter (`q2`, `qd2`, `s2`, `c2`, `p_m2`).
    pub(super) fn name(&self, id: NodeId) -> Option<Ident> {
        if let Some(name) = &self.names[id.index()] {
            return Some(name.clone());
        }
        let Node::Var(v) = self.graph.node(id) else {
            return None;
        };
        Some(local(&match v {
            Var::Q(i) => format!("q{}", i + 1),
            Var::Qd(i) => format!("qd{}", i + 1),
            Var::Qdd(i) => format!("qdd{}", i + 1),
            Var::SinQ(i) => format!("s{}", i + 1),
            Var::CosQ(i) => format!("c{}", i + 1),
            Var::Param(k) => format!("p_{}", self.eq.fields[usize::from(k)]),
            Var::Wrench(k) => crate::symbolic::WRENCH[usize::from(k)].to_owned(),
            Var::Tau(i) => format!("tau{}", i + 1),
            Var::Inertial(k) => format!("pi{}_{}", k / 10 + 1, k % 10 + 1),
            Var::Exact(k) => format!("constant{k}"),
        }))
    }

    /// A leaf (or a bound node) as written: its name, or a constant's value.
    pub(super) fn leaf(&self, id: NodeId) -> TokenStream {
        if let Some(name) = self.name(id) {
            return quote!(#name);
        }
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
                    let lit = proc_macro2::Literal::f64_unsuffixed(x);
                    quote!(#lit)
                };
                quote!(T::from_f64(#value))
            }
            _ => quote!(),
        }
    }
}

impl Sums for Emitter<'_> {
    fn graph(&self) -> &Graph {
        self.graph
    }

    fn in_place(&self, c: NodeId) -> bool {
        self.names[c.index()].is_none() && self.uses[c.index()] <= 1
    }

    fn depths(&self) -> &[Cell<u32>] {
        &self.depth
    }
}
