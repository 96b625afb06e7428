//! The outputs of the opt-in family `Simplified`: the pruned τ, M and g that the `simplify`
//! stage (`crate::simplify`) builds back into the graph, with their proven bounds.

use crate::model::Simplification;
use crate::symbolic::NodeId;

/// One pruned output element.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrunedElement {
    /// The largest `|exact − pruned|` over the envelope (the dropped terms' bounds summed).
    pub bound: f64,
    /// The tolerance it was pruned within.
    pub tolerance: f64,
    /// Terms of the exact expanded polynomial.
    pub terms: usize,
    /// Terms kept.
    pub kept: usize,
}

/// The pruned outputs, as node ids into the graph, and their bounds, element by element.
#[derive(Clone, Debug)]
pub struct SimplifiedEquations {
    /// What was asked for: the tolerances and the envelope.
    pub request: Simplification,
    /// `τ` pruned.
    pub tau: Vec<NodeId>,
    /// `M` pruned, n × n (symmetric: the same node on both sides).
    pub mass: Vec<Vec<NodeId>>,
    /// `g` pruned.
    pub gravity: Vec<NodeId>,
    /// The bounds of `tau`.
    pub tau_bounds: Vec<PrunedElement>,
    /// The bounds of `mass`, n × n.
    pub mass_bounds: Vec<Vec<PrunedElement>>,
    /// The bounds of `gravity`.
    pub gravity_bounds: Vec<PrunedElement>,
}
