//! Expression printing: a node as Rust, with `a + (−b)` written `a − b`, `x·y + z` written
//! `x.mul_add(y, z)`, the terms of a sum added in [`sum_order`], and parentheses only where
//! precedence or the order of evaluation needs them.

use super::emitter::Emitter;
use super::sum_order::{sum_order, SumTerm};
use crate::symbolic::{Node, NodeId};
use proc_macro2::TokenStream;
use quote::quote;

/// Where an expression is written, which decides whether it needs parentheses.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Place {
    /// A statement's right-hand side or an array element.
    Top,
    /// Left of `+` or `−`.
    AddLeft,
    /// Right of `+` or `−`.
    AddRight,
    /// Left of `*`.
    MulLeft,
    /// Right of `*` or `/`, or under a unary minus.
    MulRight,
    /// Before a method call's dot.
    Receiver,
}

/// A partial sum while [`Emitter::sum`] combines the terms of a sum: a term not yet written,
/// or written code and what it ends in (which decides the parentheses around it).
enum Part {
    Term(NodeId),
    Call(TokenStream),
    Sum(TokenStream),
}

impl Emitter<'_> {
    /// A node's expression at `place`: its name if it has one, else written out, in
    /// parentheses where the place needs them.
    pub(super) fn expr(&mut self, id: NodeId, place: Place) -> TokenStream {
        if self.is_leaf(id) {
            return self.leaf(id);
        }
        if let Some(name) = &self.names[id.index()] {
            return quote!(#name);
        }
        if self.is_sum(id) {
            // A fused multiply-add is a method call, which needs no parentheses.
            let (e, call) = self.sum(id);
            return if call || place == Place::Top || place == Place::AddLeft {
                e
            } else {
                quote!((#e))
            };
        }
        let wrap = match self.graph.node(id) {
            Node::Mul(..) | Node::Recip(_) => place == Place::MulRight || place == Place::Receiver,
            Node::Neg(_) => matches!(place, Place::MulRight | Place::AddRight | Place::Receiver),
            _ => false,
        };
        let e = self.define(id);
        if wrap {
            quote!((#e))
        } else {
            e
        }
    }

    /// Whether node `c` is written where it is read, not bound to a name: read once.
    pub(super) fn in_place(&self, c: NodeId) -> bool {
        self.names[c.index()].is_none() && self.uses[c.index()] <= 1
    }

    /// The terms of the sum `id` with their signs (`true`: subtracted), through the sums and
    /// negated sums written in place.
    fn sum_terms(&self, id: NodeId, negative: bool, terms: &mut Vec<(NodeId, bool)>) {
        let Node::Add(a, b) = self.graph.node(id) else {
            terms.push((id, negative));
            return;
        };
        // The operands as `operands` reads them: `a + (−x)` reads `a` and `x`.
        let (a, b, b_negative) = match self.as_sub(a, b) {
            Some((a, x)) => (a, x, !negative),
            None => (a, b, negative),
        };
        for (c, negative) in [(a, negative), (b, b_negative)] {
            let (c, negative) = match self.graph.node(c) {
                Node::Neg(x) if self.in_place(c) => (x, !negative),
                _ => (c, negative),
            };
            match self.graph.node(c) {
                Node::Add(..) if self.in_place(c) => self.sum_terms(c, negative, terms),
                _ => terms.push((c, negative)),
            }
        }
    }

    /// Whether `id` is written as a sum: a sum, or a negated sum written in place, whose terms
    /// then change sign (`−(a − x·y)` is written `x.mul_add(y, −a)`, not negated again).
    fn is_sum(&self, id: NodeId) -> bool {
        match self.graph.node(id) {
            Node::Add(..) => true,
            Node::Neg(a) => matches!(self.graph.node(a), Node::Add(..)) && self.in_place(a),
            _ => false,
        }
    }

    /// The terms of the sum [`Emitter::is_sum`] `id` with their signs, and as [`sum_order`]
    /// weighs them.
    pub(super) fn sum_terms_with_depth(
        &mut self,
        id: NodeId,
    ) -> (Vec<(NodeId, bool)>, Vec<SumTerm>) {
        let mut terms = Vec::new();
        match self.graph.node(id) {
            Node::Neg(a) => self.sum_terms(a, true, &mut terms),
            _ => self.sum_terms(id, false, &mut terms),
        }
        let weighed = terms
            .iter()
            .map(|&(t, negative)| SumTerm {
                depth: self.depth(t),
                negative,
                fusable: self.fusable(t),
            })
            .collect();
        (terms, weighed)
    }

    /// Whether `t` is a product written in place, which a fused multiply-add can take.
    pub(super) fn fusable(&self, t: NodeId) -> bool {
        matches!(self.graph.node(t), Node::Mul(..)) && self.in_place(t)
    }

    /// The sum `id` written in [`sum_order`], through the sums written in place
    /// ([`Emitter::sum_terms`]): `a + b`, `a − b` and `x.mul_add(y, a)`; `true` if it ends in
    /// `mul_add` (a method call, which needs no parentheses).
    fn sum(&mut self, id: NodeId) -> (TokenStream, bool) {
        let (terms, depths) = self.sum_terms_with_depth(id);
        let (additions, _) = sum_order(&depths);
        let mut parts: Vec<Option<(Part, bool)>> = terms
            .iter()
            .map(|&(t, negative)| Some((Part::Term(t), negative)))
            .collect();
        for addition in additions {
            let (a, b) = (parts[addition.a].take(), parts[addition.b].take());
            let (Some(a), Some(b)) = (a, b) else {
                unreachable!("each partial sum is added once");
            };
            parts.push(Some(self.combine(a, b, addition.fused)));
        }
        let Some(Some((root, negative))) = parts.pop() else {
            unreachable!("a sum has terms");
        };
        match (root, negative) {
            (Part::Call(e), false) => (e, true),
            (root, false) => (self.part(root, Place::Top), false),
            (root, true) => {
                let e = self.part(root, Place::MulRight);
                (quote!(-#e), false)
            }
        }
    }

    /// Two partial sums with their signs (`true`: negative) added: if `fused`, `b` is a
    /// product written in place, `±x·y`, and the sum is `x.mul_add(y, a)` with the sign of both
    /// if they have the same, else `(-x).mul_add(y, a)` or `x.mul_add(y, -a)`, positive (a
    /// negated operand of `mul_add` costs nothing: x86-64 and aarch64 have fused forms with
    /// either sign, and without FMA `−x·y + a` is `a − x·y`); else `a + b` or `a − b`.
    fn combine(&mut self, a: (Part, bool), b: (Part, bool), fused: bool) -> (Part, bool) {
        let product = match b.0 {
            Part::Term(t) if fused => match self.graph.node(t) {
                Node::Mul(x, y) => Some((x, y)),
                _ => None,
            },
            _ => None,
        };
        let Some((x, y)) = product else {
            return match (a.1, b.1) {
                (false, true) => (Part::Sum(self.difference(a.0, b.0)), false),
                (true, false) => (Part::Sum(self.difference(b.0, a.0)), false),
                (negative, _) => {
                    let (a, b) = (
                        self.part(a.0, Place::AddLeft),
                        self.part(b.0, Place::AddRight),
                    );
                    (Part::Sum(quote!(#a + #b)), negative)
                }
            };
        };
        let x = if b.1 && !a.1 {
            let x = self.expr(x, Place::MulRight);
            quote!((-#x))
        } else {
            self.expr(x, Place::Receiver)
        };
        let y = self.expr(y, Place::Top);
        let rest = if a.1 && !b.1 {
            let rest = self.part(a.0, Place::MulRight);
            quote!(-#rest)
        } else {
            self.part(a.0, Place::Top)
        };
        (Part::Call(quote!(#x.mul_add(#y, #rest))), a.1 && b.1)
    }

    /// `a − b`.
    fn difference(&mut self, a: Part, b: Part) -> TokenStream {
        let (a, b) = (self.part(a, Place::AddLeft), self.part(b, Place::AddRight));
        quote!(#a - #b)
    }

    /// A partial sum written at `place`.
    fn part(&mut self, part: Part, place: Place) -> TokenStream {
        let wrap = |e: TokenStream| quote!((#e));
        match part {
            Part::Term(t) => self.expr(t, place),
            Part::Call(e) => e,
            Part::Sum(e) if matches!(place, Place::Top | Place::AddLeft) => e,
            Part::Sum(e) => wrap(e),
        }
    }

    pub(super) fn define(&mut self, id: NodeId) -> TokenStream {
        if self.is_sum(id) {
            return self.sum(id).0;
        }
        match self.graph.node(id) {
            Node::Add(..) => unreachable!("a sum is written by `sum`"),
            Node::Mul(a, b) => {
                let (a, b) = (self.expr(a, Place::MulLeft), self.expr(b, Place::MulRight));
                quote!(#a * #b)
            }
            Node::Neg(a) => {
                let a = self.expr(a, Place::MulRight);
                quote!(-#a)
            }
            Node::Recip(a) => {
                let a = self.expr(a, Place::MulRight);
                quote!(T::ONE / #a)
            }
            Node::Sin(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::sin(#a))
            }
            Node::Cos(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::cos(#a))
            }
            Node::Sign(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::sign(#a))
            }
            Node::Tanh(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::tanh(#a))
            }
            Node::Const(_) | Node::Var(_) => self.leaf(id),
        }
    }
}
