//! The outputs the family `Simplified` prunes, one row per method of the family, and their
//! pruning element by element: within caps for the derive (an output past them is left
//! exact, [`Fallback`]), or without any for `dynamics inspect --simplified`.

use super::eval;
use super::prune::{mass_tolerance, prune, Pruning};
use crate::method::Method;
use crate::model::Simplification;
use crate::poly::{Expander, Limits};
use crate::symbolic::NodeId;
use crate::trace::{Equations, Fallback, Shape};

/// An output the family prunes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Output {
    /// The simplified method (`inverse_dynamics_simplified`).
    pub method: Method,
    /// The exact method whose output it prunes (`inverse_dynamics`).
    pub exact: Method,
    /// The letter of its elements' names, the book's: `T1`, `D12`, `C1`, `D1`.
    pub letter: &'static str,
}

/// The family's outputs in the order they are pruned, which shares the expansions of τ with
/// the outputs after it; each output's budget of work ([`Caps`]) was sized in this order.
pub const OUTPUTS: [Output; 4] = [
    Output {
        method: Method::InverseDynamicsSimplified,
        exact: Method::InverseDynamics,
        letter: "T",
    },
    Output {
        method: Method::GravityTorquesSimplified,
        exact: Method::GravityTorques,
        letter: "D",
    },
    Output {
        method: Method::CoriolisTorquesSimplified,
        exact: Method::CoriolisTorques,
        letter: "C",
    },
    Output {
        method: Method::MassMatrixSimplified,
        exact: Method::MassMatrix,
        letter: "D",
    },
];

/// How far the pruning of one output may go before the output is left exact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Caps {
    /// Most terms its pruned elements may keep.
    pub kept: usize,
    /// Most term operations its expansion may take.
    pub work: u64,
}

impl Caps {
    /// No cap: every output pruned, however long it takes (the command line's printout).
    pub const NONE: Caps = Caps {
        kept: usize::MAX,
        work: u64::MAX,
    };
}

/// One element's pruning: `v_i` (`column` `None`) or `M_ij`, `j ≥ i`.
pub struct Pruned {
    /// The element's row `i`.
    pub row: usize,
    /// Its column `j`, for M.
    pub column: Option<usize>,
    /// What it keeps and drops.
    pub pruning: Pruning,
}

/// One output pruned element by element (M's upper triangle), or why it is left exact.
pub struct PrunedOutput {
    /// Which output.
    pub output: Output,
    /// Its elements' prunings, row by row, or the cap it passed.
    pub elements: Result<Vec<Pruned>, Fallback>,
}

/// Prunes every output of [`OUTPUTS`] of `eq` for `request`, each within `caps`.
///
/// # Errors
/// A request whose lists are not one value per joint, an output that is not a polynomial in
/// the joint variables, or a parameter of the robot (a struct field) in an output or an angle
/// offset: no envelope bounds it.
pub fn prune_outputs(
    eq: &Equations,
    request: &Simplification,
    caps: Caps,
) -> Result<Vec<PrunedOutput>, String> {
    let n = eq.dof;
    if request.tolerance.len() != n || request.envelope.joints.len() != n {
        return Err(format!(
            "the envelope and the tolerances need one value per joint ({n})"
        ));
    }
    let constants = eval::constants(eq)?;
    let limits = Limits {
        max_terms: usize::MAX,
        max_work: caps.work,
    };
    let mut pruner = Pruner {
        expander: Expander::new(eq, limits),
        request,
        offsets: &constants.offsets,
        caps,
    };
    OUTPUTS
        .iter()
        .map(|&output| {
            let elements = match output.exact.shape(eq) {
                Shape::Vector(ids) => pruner.vector(ids, output.letter)?,
                Shape::Matrix(rows) => pruner.matrix(rows, output.letter)?,
                _ => unreachable!("the family prunes vectors and M"),
            };
            Ok(PrunedOutput { output, elements })
        })
        .collect()
}

/// Expands and prunes output elements over one request, an output at a time.
struct Pruner<'a> {
    expander: Expander<'a>,
    request: &'a Simplification,
    offsets: &'a [f64],
    caps: Caps,
}

/// An output pruned element by element, or why it is left exact.
type Outcome<T> = Result<T, Fallback>;

impl Pruner<'_> {
    /// Element `id`, named `name` in errors, pruned within `tolerance`; `Ok(None)` when the
    /// output's budget of work ran out first.
    fn one(&mut self, id: NodeId, name: &str, tolerance: f64) -> Result<Option<Pruning>, String> {
        let Some(full) = self.expander.folded(id) else {
            if self.expander.exhausted() {
                return Ok(None);
            }
            return Err(format!("{name} is not a polynomial in the joint variables"));
        };
        let pruning = prune(full, &self.request.envelope, self.offsets, tolerance)
            .map_err(|e| format!("{name}: {e}"))?;
        Ok(Some(pruning))
    }

    /// Element `id` of an output whose elements have kept `kept` terms so far.
    fn counted(
        &mut self,
        id: NodeId,
        name: &str,
        tolerance: f64,
        kept: &mut usize,
    ) -> Result<Outcome<Pruning>, String> {
        let Some(p) = self.one(id, name, tolerance)? else {
            return Ok(Err(Fallback::TooMuchWork {
                budget: self.caps.work,
            }));
        };
        *kept += p.kept.len();
        if *kept > self.caps.kept {
            return Ok(Err(Fallback::TooManyTerms {
                kept: *kept,
                cap: self.caps.kept,
            }));
        }
        Ok(Ok(p))
    }

    /// A vector of elements, `T1`, `T2`, …, each within its joint's tolerance.
    fn vector(&mut self, ids: &[NodeId], letter: &str) -> Result<Outcome<Vec<Pruned>>, String> {
        self.expander.renew_budget();
        let mut kept = 0;
        let mut out = Vec::with_capacity(ids.len());
        for (i, (&id, &t)) in ids.iter().zip(&self.request.tolerance).enumerate() {
            let name = format!("{letter}{}", i + 1);
            match self.counted(id, &name, t, &mut kept)? {
                Ok(pruning) => out.push(Pruned {
                    row: i,
                    column: None,
                    pruning,
                }),
                Err(f) => return Ok(Err(f)),
            }
        }
        Ok(Ok(out))
    }

    /// M's upper triangle, row by row, each element within its [`mass_tolerance`].
    fn matrix(
        &mut self,
        rows: &[Vec<NodeId>],
        letter: &str,
    ) -> Result<Outcome<Vec<Pruned>>, String> {
        self.expander.renew_budget();
        let (t, envelope) = (&self.request.tolerance, &self.request.envelope);
        let mut kept = 0;
        let mut out = Vec::new();
        for (i, row) in rows.iter().enumerate() {
            for (j, &id) in row.iter().enumerate().skip(i) {
                let tolerance = mass_tolerance(t, envelope, i, j);
                let name = format!("{letter}{}{}", i + 1, j + 1);
                match self.counted(id, &name, tolerance, &mut kept)? {
                    Ok(pruning) => out.push(Pruned {
                        row: i,
                        column: Some(j),
                        pruning,
                    }),
                    Err(f) => return Ok(Err(f)),
                }
            }
        }
        Ok(Ok(out))
    }
}
