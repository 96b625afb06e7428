//! [`Expr`]: a node of a shared [`Graph`] with arithmetic operators, so that an algorithm
//! written once over [`Scalar`] is traced into the graph when run on `Expr`.

use crate::algo::Scalar;
use crate::symbolic::{Graph, NodeId, Number};
use std::cell::RefCell;
use std::ops::{Add, Mul, Neg, Sub};

/// A handle to a node of a graph shared through a `RefCell`.
#[derive(Clone, Copy)]
pub struct Expr<'g> {
    graph: &'g RefCell<Graph>,
    id: NodeId,
}

impl<'g> Expr<'g> {
    /// The handle of node `id` of `graph`.
    #[must_use]
    pub fn new(graph: &'g RefCell<Graph>, id: NodeId) -> Expr<'g> {
        Expr { graph, id }
    }

    /// The node.
    #[must_use]
    pub fn id(self) -> NodeId {
        self.id
    }

    fn with(self, f: impl FnOnce(&mut Graph) -> NodeId) -> Expr<'g> {
        let id = f(&mut self.graph.borrow_mut());
        Expr {
            graph: self.graph,
            id,
        }
    }
}

impl std::fmt::Debug for Expr<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.id)
    }
}

impl<'g> Add for Expr<'g> {
    type Output = Expr<'g>;
    fn add(self, rhs: Expr<'g>) -> Expr<'g> {
        self.with(|g| g.add(self.id, rhs.id))
    }
}

impl<'g> Sub for Expr<'g> {
    type Output = Expr<'g>;
    fn sub(self, rhs: Expr<'g>) -> Expr<'g> {
        self.with(|g| g.sub(self.id, rhs.id))
    }
}

impl<'g> Mul for Expr<'g> {
    type Output = Expr<'g>;
    fn mul(self, rhs: Expr<'g>) -> Expr<'g> {
        self.with(|g| g.mul(self.id, rhs.id))
    }
}

impl<'g> Neg for Expr<'g> {
    type Output = Expr<'g>;
    fn neg(self) -> Expr<'g> {
        self.with(|g| g.neg(self.id))
    }
}

impl Scalar for Expr<'_> {
    fn constant(self, c: Number) -> Self {
        self.with(|g| g.num(c))
    }

    fn is_constant(self) -> bool {
        self.graph.borrow().constant(self.id).is_some()
    }

    fn is_zero(self) -> bool {
        self.graph.borrow().is_zero(self.id)
    }

    fn recip(self) -> Self {
        let r = self.graph.borrow_mut().recip(self.id);
        r.map_or_else(|| self.zero(), |id| Expr::new(self.graph, id))
    }
}
