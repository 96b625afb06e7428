//! Expansion of the graph's outputs into their canonical polynomials, within [`Limits`]:
//! expanded polynomials grow fast with the number of joints (the code is emitted from the
//! shared graph, never from these), so what does not fit is reported as too large.

use super::fold::fold_trig;
use super::{Monomial, Poly, Sym};
use crate::symbolic::{Node, NodeId, Number};
use crate::trace::Equations;
use std::collections::BTreeMap;

/// Bounds on the polynomial expansion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Most terms of any one polynomial, intermediate ones included.
    pub max_terms: usize,
    /// Most term operations in all (each product of two terms, each term added).
    pub max_work: u64,
}

impl Limits {
    /// For the derive, which runs on every build and must stay fast: small robots print in
    /// full, a 6-joint arm's gravity torques (and PUMA 560's D_ij and D_ijk) still do. A term
    /// operation costs a few microseconds, as monomials are keyed by parameter names.
    pub const DERIVE: Limits = Limits {
        max_terms: 200,
        max_work: 20_000,
    };
    /// For the command-line tool: no bound.
    pub const UNBOUNDED: Limits = Limits {
        max_terms: usize::MAX,
        max_work: u64::MAX,
    };
}

/// Expands graph nodes into polynomials, sharing the work (and the budget of [`Limits`])
/// between outputs.
pub struct Expander<'a> {
    eq: &'a Equations,
    memo: Vec<Option<Option<Poly>>>,
    /// Marks of the search in [`Expander::poly`], all false between searches.
    seen: Vec<bool>,
    limits: Limits,
    work: u64,
}

impl<'a> Expander<'a> {
    /// An expander of the outputs of `eq` within `limits`.
    #[must_use]
    pub fn new(eq: &'a Equations, limits: Limits) -> Expander<'a> {
        Expander {
            eq,
            memo: vec![None; eq.graph.len()],
            seen: vec![false; eq.graph.len()],
            limits,
            work: 0,
        }
    }

    /// A new budget of work for further outputs, keeping the polynomials found so far: the
    /// nodes that did not fit the old budget are tried again.
    pub(crate) fn renew_budget(&mut self) {
        self.work = 0;
        for p in &mut self.memo {
            if matches!(p, Some(None)) {
                *p = None;
            }
        }
    }

    /// The polynomial of node `id`; `None` when it exceeds the limits or is not a polynomial
    /// (a reciprocal or the sine of a parameter).
    fn poly(&mut self, id: NodeId) -> Option<Poly> {
        if let Some(p) = &self.memo[id.index()] {
            return p.clone();
        }
        // The nodes it reads that are not expanded yet, children first (the arena's order):
        // a search that stops at expanded nodes, so each output costs what is new in it.
        let mut todo = Vec::new();
        let mut stack = vec![id];
        while let Some(n) = stack.pop() {
            if self.memo[n.index()].is_some() || std::mem::replace(&mut self.seen[n.index()], true)
            {
                continue;
            }
            todo.push(n);
            stack.extend(self.eq.graph.node(n).operands());
        }
        todo.sort_unstable();
        for n in todo {
            self.seen[n.index()] = false;
            let p = self.node(self.eq.graph.node(n));
            self.memo[n.index()] = Some(p);
        }
        self.memo[id.index()].clone().flatten()
    }

    fn node(&mut self, node: Node) -> Option<Poly> {
        // The operands by reference: a polynomial cloned is every monomial allocated again.
        let memo = &self.memo;
        let get = |x: NodeId| memo[x.index()].as_ref().and_then(Option::as_ref);
        let (work, max_work) = (&mut self.work, self.limits.max_work);
        let mut charge = |cost: u64| {
            *work = work.saturating_add(cost);
            (*work <= max_work).then_some(())
        };
        let p = match node {
            Node::Const(c) => Poly::constant(c),
            Node::Var(v) => Poly::sym(Sym::of(v, &self.eq.fields)?),
            Node::Add(a, b) => {
                let (a, b) = (get(a)?, get(b)?);
                charge((a.len() + b.len()) as u64)?;
                a.add(b)
            }
            Node::Mul(a, b) => {
                let (a, b) = (get(a)?, get(b)?);
                charge((a.len() as u64).saturating_mul(b.len() as u64))?;
                a.mul(b)
            }
            Node::Neg(a) => get(a)?.scale(Number::MINUS_ONE),
            Node::Sign(_) | Node::Tanh(_) => Poly::sym(Sym::of_friction(&self.eq.graph, node)?),
            // A mimic joint's `sin(k q_j + c)`: a symbol of its own.
            Node::Sin(a) | Node::Cos(a) => {
                Poly::sym(Sym::mimic_trig(matches!(node, Node::Cos(_)), get(a)?)?)
            }
            Node::Recip(_) => return None,
        };
        (p.len() <= self.limits.max_terms).then_some(p)
    }

    /// Whether the budget of work ran out since it was last renewed: a `None` may then be a
    /// polynomial too large to finish rather than no polynomial.
    pub(crate) fn exhausted(&self) -> bool {
        self.work > self.limits.max_work
    }

    fn charge(&mut self, cost: u64) -> Option<()> {
        self.work = self.work.saturating_add(cost);
        (self.work <= self.limits.max_work).then_some(())
    }

    /// The polynomial of node `id`, before folding.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn expanded(&mut self, id: NodeId) -> Option<BTreeMap<Monomial, Number>> {
        Some(self.poly(id)?.into_terms())
    }

    /// The polynomial of node `id` with its sines and cosines of sums folded (`C12`), an
    /// identity; `None` when it does not fit the limits.
    pub fn folded(&mut self, id: NodeId) -> Option<BTreeMap<Monomial, Number>> {
        let mut terms = self.poly(id)?.into_terms();
        // Each search for a pair to fold reads every term.
        fold_trig(&mut terms, &mut |n| self.charge(n as u64))?;
        Some(terms)
    }
}
