//! Expression printing: a node as Rust, with `a + (−b)` written `a − b`, `x·y + z` written
//! `x.mul_add(y, z)`, the terms of a sum added as [`Sums::plan`] orders them, and parentheses only where
//! precedence or the order of evaluation needs them.

use super::emitter::Emitter;
use super::sums::{Sums, Written};
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

    /// The sum `id` as [`Sums::plan`] writes it: `a + b`, `a − b` and `x.mul_add(y, a)`;
    /// `true` if it ends in `mul_add` (a method call, which needs no parentheses).
    fn sum(&mut self, id: NodeId) -> (TokenStream, bool) {
        match self.plan(id) {
            (root @ Written::MulAdd { .. }, false) => (self.written(root, Place::Top), true),
            (root, false) => (self.written(root, Place::Top), false),
            (root, true) => {
                let e = self.written(root, Place::MulRight);
                (quote!(-#e), false)
            }
        }
    }

    /// A planned partial sum at `place`.
    fn written(&mut self, w: Written, place: Place) -> TokenStream {
        let (a, b, minus) = match w {
            Written::Term(t) => return self.expr(t, place),
            Written::MulAdd {
                x,
                y,
                negate_x,
                addend,
                negate_addend,
            } => {
                let x = if negate_x {
                    let x = self.expr(x, Place::MulRight);
                    quote!((-#x))
                } else {
                    self.expr(x, Place::Receiver)
                };
                let y = self.expr(y, Place::Top);
                let rest = if negate_addend {
                    let rest = self.written(*addend, Place::MulRight);
                    quote!(-#rest)
                } else {
                    self.written(*addend, Place::Top)
                };
                return quote!(#x.mul_add(#y, #rest));
            }
            Written::Add(a, b) => (a, b, false),
            Written::Sub(a, b) => (a, b, true),
        };
        let (a, b) = (
            self.written(*a, Place::AddLeft),
            self.written(*b, Place::AddRight),
        );
        let e = if minus {
            quote!(#a - #b)
        } else {
            quote!(#a + #b)
        };
        if matches!(place, Place::Top | Place::AddLeft) {
            e
        } else {
            quote!((#e))
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
