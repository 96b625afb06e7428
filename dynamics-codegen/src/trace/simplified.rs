//! The outputs of the opt-in family `Simplified`: the pruned τ, M and g that the `simplify`
//! stage (`crate::simplify`) builds back into the graph, with their proven bounds.

use crate::method::Method;
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

/// The pruned outputs, one row per method of the family, as node ids into the graph, with
/// their proven bounds element by element.
#[derive(Clone, Debug)]
pub struct SimplifiedEquations {
    /// What was asked for: the tolerances and the envelope.
    pub request: Simplification,
    /// The outputs, in the order the stage pruned them.
    pub outputs: Vec<SimplifiedOutput>,
}

impl SimplifiedEquations {
    /// The output of the simplified method `method`, if it is one of the family's.
    #[must_use]
    pub fn output(&self, method: Method) -> Option<&SimplifiedOutput> {
        self.outputs.iter().find(|o| o.method == method)
    }
}

/// One simplified method's output.
#[derive(Clone, Debug)]
pub struct SimplifiedOutput {
    /// The simplified method (`inverse_dynamics_simplified`).
    pub method: Method,
    /// The exact method whose output it prunes (`inverse_dynamics`).
    pub exact: Method,
    /// The letter of its elements' names, the book's: `T1`, `D12`, `C1`, `D1`.
    pub letter: &'static str,
    /// The pruned elements.
    pub elements: Elements<NodeId>,
    /// Each element's bound, in the layout of `elements`.
    pub bounds: Elements<PrunedElement>,
    /// Why the elements are the exact ones, if they are.
    pub fallback: Option<Fallback>,
}

impl SimplifiedOutput {
    /// Each element's name and bound once (a matrix's upper triangle, `D11`, `D12`, …), with
    /// the joint of a vector's element (for its unit).
    pub fn named_bounds(&self) -> impl Iterator<Item = (String, Option<usize>, &PrunedElement)> {
        let letter = self.letter;
        self.bounds.upper().map(move |(i, j, b)| match j {
            None => (format!("{letter}{}", i + 1), Some(i), b),
            Some(j) => (format!("{letter}{}{}", i + 1, j + 1), None, b),
        })
    }
}

/// An output's elements: one per joint, or n × n (M, symmetric: the same value both sides).
#[derive(Clone, Debug, PartialEq)]
pub enum Elements<T> {
    /// `v_i`.
    Vector(Vec<T>),
    /// `M_ij`, row by row.
    Matrix(Vec<Vec<T>>),
}

impl<T> Elements<T> {
    /// Each element once, `(i, None, v_i)`, or a matrix's upper triangle `(i, Some(j), M_ij)`
    /// for `j ≥ i`, row by row.
    pub fn upper(&self) -> impl Iterator<Item = (usize, Option<usize>, &T)> {
        let (vector, matrix): (&[T], &[Vec<T>]) = match self {
            Elements::Vector(v) => (v, &[]),
            Elements::Matrix(m) => (&[], m),
        };
        let vector = vector.iter().enumerate().map(|(i, v)| (i, None, v));
        let matrix = matrix.iter().enumerate().flat_map(|(i, row)| {
            row.iter()
                .enumerate()
                .skip(i)
                .map(move |(j, v)| (i, Some(j), v))
        });
        vector.chain(matrix)
    }

    /// Every element, a matrix's row by row.
    pub fn all(&self) -> impl Iterator<Item = &T> {
        let (vector, matrix): (&[T], &[Vec<T>]) = match self {
            Elements::Vector(v) => (v, &[]),
            Elements::Matrix(m) => (&[], m),
        };
        vector.iter().chain(matrix.iter().flatten())
    }
}
