//! The graph's vocabulary: node ids, leaves (the generated function's inputs) and operations.

use super::number::Number;
use std::fmt;

/// Index of a node in a [`Graph`](super::Graph); displayed as `t12`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeId(pub u32);

impl NodeId {
    /// The index into the arena.
    #[must_use]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl fmt::Display for NodeId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "t{}", self.0)
    }
}

/// A leaf of the graph: an input of the generated function.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Var {
    /// Position `q_i` (0-based joint index).
    Q(u16),
    /// `sin(q_i + offset_i)` of a revolute joint.
    SinQ(u16),
    /// `cos(q_i + offset_i)` of a revolute joint.
    CosQ(u16),
    /// Velocity `qd_i`.
    Qd(u16),
    /// Acceleration `qdd_i`.
    Qdd(u16),
    /// Robot parameter `k` (a struct field).
    Param(u16),
    /// Component `k` of a wrench `[fx, fy, fz, mx, my, mz]` (an argument of the statics).
    Wrench(u16),
    /// Joint torque or force `τ_i` (an argument of the forward dynamics).
    Tau(u16),
    /// Component `k % 6` of the wrench at tip `k / 6` (an argument of the tips' statics).
    TipWrench(u16),
    /// Standard inertial parameter `k % 10` of link `k / 10`: a placeholder of the regressor's
    /// trace, replaced by 0 or 1 for each of its columns and never emitted.
    Inertial(u16),
    /// Constant `k` of the description (a number, or the sine or cosine of an angle), as a
    /// leaf: in the base parameters' exact analysis only, which has its value in `ℤ/p`, so that
    /// no product of constants is folded into a float. Never emitted.
    Exact(u16),
}

/// The names of a wrench's components, [`Var::Wrench`]`(k)` for `k` from 0.
pub const WRENCH: [&str; 6] = ["fx", "fy", "fz", "mx", "my", "mz"];

/// A node of the graph.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// A constant.
    Const(Number),
    /// An input.
    Var(Var),
    /// `a + b`.
    Add(NodeId, NodeId),
    /// `a · b`.
    Mul(NodeId, NodeId),
    /// `−a`.
    Neg(NodeId),
    /// `1 / a`.
    Recip(NodeId),
    /// `sin a` (of a parameter expression; joint angles use [`Var::SinQ`]).
    Sin(NodeId),
    /// `cos a`.
    Cos(NodeId),
    /// `sign a`: −1, 0 or 1, 0 at 0 (Coulomb friction, `Real::sign`).
    Sign(NodeId),
    /// `tanh a` (smooth Coulomb friction).
    Tanh(NodeId),
}

impl Node {
    /// Its operands, none for a leaf.
    pub fn operands(self) -> impl Iterator<Item = NodeId> {
        let (a, b) = match self {
            Node::Add(a, b) | Node::Mul(a, b) => (Some(a), Some(b)),
            Node::Neg(a)
            | Node::Recip(a)
            | Node::Sin(a)
            | Node::Cos(a)
            | Node::Sign(a)
            | Node::Tanh(a) => (Some(a), None),
            Node::Const(_) | Node::Var(_) => (None, None),
        };
        a.into_iter().chain(b)
    }
}
