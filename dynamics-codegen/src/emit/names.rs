//! The names of output elements (`m1_2` for M₁₂, `g3` for g₃, `tau3` for τ₃, `p`), typed: an
//! element is its method and its index, which give both its name and its doc comment.

use crate::method::Method;
use crate::symbolic::NodeId;
use crate::trace::Shape;
use proc_macro2::{Ident, Span};

/// Name of the configuration struct.
pub const CONFIGURATION_STRUCT: &str = "Configuration";
/// Name of the function computing it, `configuration(p_, q_)`.
pub const CONFIGURATION_FN: &str = "configuration";
/// Name of the struct of terms in `q̇` that several methods share.
pub const MOTION_STRUCT: &str = "Motion";
/// Name of the function computing it with the configuration, `motion(p_, q_, qd_)`.
pub const MOTION_FN: &str = "motion";
/// Name of the local holding the configuration in the motion function.
pub const CONFIGURATION_LOCAL: &str = "c_";
/// Name of the argument a result written in place goes to (`&mut`, the result's type).
pub const OUTPUT: &str = "y_";
/// Name of the argument a group of `∂q̈`'s rows stores its `q̈` into (`emit/rows.rs`).
pub const SOLUTION: &str = "x_";
/// Name of the argument holding the robot's parameters, `[T; K]` in the order of
/// `Equations::fields`.
pub const PARAMETERS: &str = "p_";

/// A name the generated code binds (see `Generated::items` for why no user item can
/// take its place).
pub fn local(name: &str) -> Ident {
    Ident::new(name, Span::mixed_site())
}

/// An element of a method's result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Element {
    method: Method,
    index: Index,
}

/// Where an element sits in its result, from 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Index {
    Scalar,
    Vector(usize),
    Matrix(usize, usize),
    Stack(usize, usize, usize),
}

impl Element {
    /// Its local: the method's prefix and the index from 1, `m1_2`, `tau3`, `p`.
    pub(crate) fn ident(self) -> Ident {
        let prefix = self.method.prefix();
        local(&match self.index {
            Index::Scalar => prefix.to_owned(),
            Index::Vector(i) => format!("{prefix}{}", i + 1),
            Index::Matrix(i, j) => format!("{prefix}{}_{}", i + 1, j + 1),
            Index::Stack(k, i, j) => format!("{prefix}{}_{}_{}", k + 1, i + 1, j + 1),
        })
    }

    /// What it is, in the book's terms ([`Method::describe`]).
    pub(crate) fn describe(self) -> String {
        let (k, i, j) = match self.index {
            Index::Scalar => (0, 0, 0),
            Index::Vector(i) => (0, i, 0),
            Index::Matrix(i, j) => (0, i, j),
            Index::Stack(k, i, j) => (k, i, j),
        };
        self.method.describe_in(k, i, j)
    }
}

/// The output elements of `method`, whose result is `shape`, by node, leaves (which keep
/// their own names) left out; an element equal to an earlier one (M's lower triangle) keeps
/// the earlier name.
pub(crate) fn output_names(
    shape: &Shape,
    method: Method,
    is_leaf: impl Fn(NodeId) -> bool,
) -> Vec<(NodeId, Element)> {
    let mut named: Vec<(NodeId, Element)> = Vec::new();
    let mut seen = std::collections::BTreeSet::new();
    let mut add = |id: NodeId, index: Index| {
        if !is_leaf(id) && seen.insert(id) {
            named.push((id, Element { method, index }));
        }
    };
    match shape {
        Shape::Scalar(id) => add(*id, Index::Scalar),
        Shape::Vector(v) | Shape::SolvedVector { vector: v, .. } => {
            for (i, &id) in v.iter().enumerate() {
                add(id, Index::Vector(i));
            }
        }
        Shape::Matrix(m) | Shape::SolvedMatrix { matrix: m, .. } => {
            for (i, row) in m.iter().enumerate() {
                for (j, &id) in row.iter().enumerate() {
                    add(id, Index::Matrix(i, j));
                }
            }
        }
        // The vector of a solved stack (`q̈` beside its derivatives) keeps temporaries'
        // names: the element names say what a block's entries are.
        Shape::Stack(s) | Shape::SolvedStack { stack: s, .. } | Shape::Lanes { stack: s, .. } => {
            for (k, m) in s.iter().enumerate() {
                for (i, row) in m.iter().enumerate() {
                    for (j, &id) in row.iter().enumerate() {
                        add(id, Index::Stack(k, i, j));
                    }
                }
            }
        }
    }
    named
}
