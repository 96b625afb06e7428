//! The outputs of the opt-in family `Simplified`: the pruned τ, M and g that the `simplify`
//! stage (`crate::simplify`) builds back into the graph, with their proven bounds.

use crate::model::Simplification;
use crate::symbolic::NodeId;

use std::fmt;

/// One pruned output element.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrunedElement {
    /// The largest `|exact − pruned|` over the envelope (the dropped terms' bounds summed);
    /// 0 in an output left exact ([`Fallback`]).
    pub bound: f64,
    /// The tolerance it was pruned within.
    pub tolerance: f64,
    /// Terms of the exact expanded polynomial; 0 in an output left exact.
    pub terms: usize,
    /// Terms kept; 0 in an output left exact.
    pub kept: usize,
}

/// Why an output of the family is its exact value (bound 0) rather than pruned: its expanded
/// form would cost far more than the exact recursive one, so the request gains nothing there,
/// while the other outputs are still pruned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fallback {
    /// Its pruned elements keep `kept` terms or more (the count stops once past the cap),
    /// more than `cap`.
    TooManyTerms {
        /// Terms kept by the elements pruned before the count passed the cap.
        kept: usize,
        /// Most terms a pruned output may keep.
        cap: usize,
    },
    /// Expanding it took more than `budget` term operations (products of two terms, terms
    /// added, terms read in a search for a fold) before it was done.
    TooMuchWork {
        /// Most term operations the expansion of one output may take.
        budget: u64,
    },
}

impl fmt::Display for Fallback {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fallback::TooManyTerms { kept, cap } => write!(
                f,
                "its pruned expansion keeps {kept} terms or more, more than the cap of {cap}; \
                 expanded, it would cost far more than the exact form"
            ),
            Fallback::TooMuchWork { budget } => write!(
                f,
                "its expansion took more than {budget} term operations, the cap that keeps the \
                 derive fast; expanded, it would cost far more than the exact form"
            ),
        }
    }
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
    /// `C q̇` pruned.
    pub coriolis_torques: Vec<NodeId>,
    /// `g` pruned.
    pub gravity: Vec<NodeId>,
    /// The bounds of `tau`.
    pub tau_bounds: Vec<PrunedElement>,
    /// The bounds of `mass`, n × n.
    pub mass_bounds: Vec<Vec<PrunedElement>>,
    /// The bounds of `coriolis_torques`.
    pub coriolis_torques_bounds: Vec<PrunedElement>,
    /// The bounds of `gravity`.
    pub gravity_bounds: Vec<PrunedElement>,
    /// Why `tau` is the exact torques, if it is.
    pub tau_fallback: Option<Fallback>,
    /// Why `mass` is the exact mass matrix, if it is.
    pub mass_fallback: Option<Fallback>,
    /// Why `coriolis_torques` is the exact `C q̇`, if it is.
    pub coriolis_torques_fallback: Option<Fallback>,
    /// Why `gravity` is the exact gravity torques, if it is.
    pub gravity_fallback: Option<Fallback>,
}
