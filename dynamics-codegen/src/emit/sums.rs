//! The plan of a sum, which the Rust and the C printers both write: its terms through the sums
//! written in place, added in [`sum_order`], a product fused into a multiply-add with the
//! partial sum it meets. One plan, two printers: the C computes what the Rust computes, in the
//! same order, and so gets the same bits where both fuse alike.

use super::sum_order::{sum_depth, sum_order, SumTerm};
use crate::symbolic::{Graph, Node, NodeId};
use std::cell::Cell;

/// A sum as it is written, the signs resolved: every partial sum positive but the root's.
pub(crate) enum Written {
    /// A term, written as its node is.
    Term(NodeId),
    /// `a + b`.
    Add(Box<Written>, Box<Written>),
    /// `a − b`.
    Sub(Box<Written>, Box<Written>),
    /// `x·y + a` in one fused multiply-add, with `x` negated (`(−x)·y + a`) or the addend
    /// (`x·y − a`) where the signs differ: a negated operand costs nothing (x86-64 and aarch64
    /// have fused forms with either sign, and without FMA `−x·y + a` is `a − x·y`).
    MulAdd {
        x: NodeId,
        y: NodeId,
        negate_x: bool,
        addend: Box<Written>,
        negate_addend: bool,
    },
}

/// What a printer tells the plan: its graph, which nodes it writes where they are read, and
/// where it keeps each node's depth once computed.
pub(crate) trait Sums {
    fn graph(&self) -> &Graph;

    /// Whether node `c` is written where it is read, not bound to a name.
    fn in_place(&self, c: NodeId) -> bool;

    /// Each node's depth ([`Sums::depth`]), `u32::MAX` until asked for.
    fn depths(&self) -> &[Cell<u32>];

    /// Keeps node `id`'s depth once computed, in [`Sums::depths`].
    fn remember_depth(&self, id: NodeId, depth: u32) {
        self.depths()[id.index()].set(depth);
    }

    /// `(a, x)` if `a + b` is `a − x`.
    fn as_sub(&self, a: NodeId, b: NodeId) -> Option<(NodeId, NodeId)> {
        as_sub(self.graph(), a, b)
    }

    /// Whether `id` is written as a sum: a sum, or a negated sum written in place, whose terms
    /// then change sign (`−(a − x·y)` is written `x·y − a`, not negated again).
    fn is_sum(&self, id: NodeId) -> bool {
        match self.graph().node(id) {
            Node::Add(..) => true,
            Node::Neg(a) => matches!(self.graph().node(a), Node::Add(..)) && self.in_place(a),
            _ => false,
        }
    }

    /// Whether `t` is a product written in place, which a fused multiply-add can take.
    fn fusable(&self, t: NodeId) -> bool {
        matches!(self.graph().node(t), Node::Mul(..)) && self.in_place(t)
    }

    /// The terms of the sum `id` with their signs (`true`: subtracted), through the sums and
    /// negated sums written in place.
    fn sum_terms(&self, id: NodeId, negative: bool, terms: &mut impl Extend<(NodeId, bool)>) {
        let Node::Add(a, b) = self.graph().node(id) else {
            terms.extend([(id, negative)]);
            return;
        };
        // The operands as the printers read them: `a + (−x)` reads `a` and `x`.
        let (a, b, b_negative) = match self.as_sub(a, b) {
            Some((a, x)) => (a, x, !negative),
            None => (a, b, negative),
        };
        for (c, negative) in [(a, negative), (b, b_negative)] {
            let (c, negative) = match self.graph().node(c) {
                Node::Neg(x) if self.in_place(c) => (x, !negative),
                _ => (c, negative),
            };
            match self.graph().node(c) {
                Node::Add(..) if self.in_place(c) => self.sum_terms(c, negative, terms),
                _ => terms.extend([(c, negative)]),
            }
        }
    }

    /// The terms of the sum [`Sums::is_sum`] `id` with their signs, and as [`sum_order`]
    /// weighs them.
    fn weighed_terms(&self, id: NodeId) -> (Vec<(NodeId, bool)>, Vec<SumTerm>) {
        let mut terms = Vec::new();
        match self.graph().node(id) {
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

    /// The number of dependent operations from the inputs to node `id` as written, each sum
    /// added in [`sum_order`]. A fused multiply-add counts as its two operations, as in the
    /// flop counts; a negation folds into what reads it.
    fn depth(&self, id: NodeId) -> u32 {
        let known = self.depths()[id.index()].get();
        if known != u32::MAX {
            return known;
        }
        let d = match self.graph().node(id) {
            Node::Add(..) => {
                // On the stack: every sum of every function asks for its depth.
                let mut terms = Inline::new((id, false));
                self.sum_terms(id, false, &mut terms);
                let weigh = |&(t, negative): &(NodeId, bool)| SumTerm {
                    depth: self.depth(t),
                    negative,
                    fusable: self.fusable(t),
                };
                let mut weighed = Inline::new(SumTerm {
                    depth: 0,
                    negative: false,
                    fusable: false,
                });
                weighed.extend(terms.as_slice().iter().map(weigh));
                sum_depth(weighed.as_slice())
            }
            Node::Mul(a, b) => 1 + self.depth(a).max(self.depth(b)),
            Node::Recip(a) | Node::Sin(a) | Node::Cos(a) | Node::Sign(a) | Node::Tanh(a) => {
                1 + self.depth(a)
            }
            Node::Neg(a) => self.depth(a),
            Node::Const(_) | Node::Var(_) => 0,
        };
        self.remember_depth(id, d);
        d
    }

    /// The sum [`Sums::is_sum`] `id` as written, and whether the whole is negated.
    fn plan(&self, id: NodeId) -> (Written, bool) {
        let (terms, weighed) = self.weighed_terms(id);
        let (additions, _) = sum_order(&weighed);
        let mut parts: Vec<Option<(Written, bool)>> = terms
            .into_iter()
            .map(|(t, negative)| Some((Written::Term(t), negative)))
            .collect();
        for addition in additions {
            let (Some(a), Some(b)) = (parts[addition.a].take(), parts[addition.b].take()) else {
                unreachable!("each partial sum is added once");
            };
            parts.push(Some(self.combine(a, b, addition.fused)));
        }
        let Some(Some(root)) = parts.pop() else {
            unreachable!("a sum has terms");
        };
        root
    }

    /// Two partial sums with their signs (`true`: negative) added: if `fused`, `b` is a
    /// product written in place and the two are one multiply-add; else `a + b` or `a − b`.
    fn combine(&self, a: (Written, bool), b: (Written, bool), fused: bool) -> (Written, bool) {
        let product = match b.0 {
            Written::Term(t) if fused => match self.graph().node(t) {
                Node::Mul(x, y) => Some((x, y)),
                _ => None,
            },
            _ => None,
        };
        let Some((x, y)) = product else {
            return match (a.1, b.1) {
                (false, true) => (Written::Sub(Box::new(a.0), Box::new(b.0)), false),
                (true, false) => (Written::Sub(Box::new(b.0), Box::new(a.0)), false),
                (negative, _) => (Written::Add(Box::new(a.0), Box::new(b.0)), negative),
            };
        };
        let fused = Written::MulAdd {
            x,
            y,
            negate_x: b.1 && !a.1,
            addend: Box::new(a.0),
            negate_addend: a.1 && !b.1,
        };
        (fused, a.1 && b.1)
    }
}

/// A short list kept on the stack, spilled to the heap past its capacity.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Inline<T: Copy> {
    items: [T; 8],
    len: usize,
    spilled: Vec<T>,
}

impl<T: Copy> Inline<T> {
    /// An empty list, its slots filled with `fill` (never read).
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn new(fill: T) -> Inline<T> {
        Inline {
            items: [fill; 8],
            len: 0,
            spilled: Vec::new(),
        }
    }

    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn as_slice(&self) -> &[T] {
        if self.spilled.is_empty() {
            &self.items[..self.len]
        } else {
            &self.spilled
        }
    }
}

impl<T: Copy> Extend<T> for Inline<T> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, items: I) {
        for item in items {
            if self.spilled.is_empty() && self.len < self.items.len() {
                self.items[self.len] = item;
                self.len += 1;
            } else {
                if self.spilled.is_empty() {
                    self.spilled.extend_from_slice(&self.items);
                }
                self.spilled.push(item);
            }
        }
    }
}

/// `(a, x)` if `a + b` is `a − x`.
pub(crate) fn as_sub(graph: &Graph, a: NodeId, b: NodeId) -> Option<(NodeId, NodeId)> {
    match (graph.node(a), graph.node(b)) {
        (_, Node::Neg(x)) => Some((a, x)),
        (Node::Neg(x), _) => Some((b, x)),
        _ => None,
    }
}
