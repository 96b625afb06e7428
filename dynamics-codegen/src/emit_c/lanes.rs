//! The inverse dynamics' derivatives with their tangents in lanes, as the Rust emission writes
//! them where the build has AVX-512 ([`crate::symbolic::Tangents`]): each lane an array of `n`
//! rounded up to eight values (`double dq3[8]`, one direction a value), written by one loop
//! right after the node it is the tangent of, which compilers turn into vector instructions,
//! and the rows of a Jacobian copied off the output lanes. The header compiles this form where
//! `DYNAMICS_TANGENT_LANES` is 1 (by default where gcc targets AVX-512, the function then asking
//! for 512-bit vectors: `DYNAMICS_LANES_WIDE`), the columns one by one from their nodes
//! otherwise (`emit_c/mod.rs` defines both macros).
//!
//! A lane `Σ ± f · e_j + Σ ± f₁ f₂ · x` is, per value `k_`, each direction's units as the row
//! of the identity `dynamics_unit[j][k_]` times their sum, then each term folded in:
//! `dynamics_fma(x[k_], f₁ * f₂, acc)`, `acc ± x[k_]`.

use super::expr::Writer;
use crate::emit::lanes::{lane_text, width, Queue};
use crate::emit::plan::Place;
use crate::symbolic::{NodeId, Of, Tangents, Term};
use crate::trace::Shape;

impl Writer<'_> {
    /// Makes every factor of `shape`'s plans a bound value, read by name.
    pub(super) fn bind_factors(&mut self, shape: &Shape) {
        let Shape::Lanes { lanes, .. } = shape else {
            return;
        };
        for f in lanes.iter().flatten().flat_map(Tangents::factors) {
            let i = f.index();
            self.uses[i] = self.uses[i].max(2);
        }
    }

    /// The lines of the lanes due before node `before` (all those left for `None`).
    pub(super) fn lanes_due(
        &self,
        queue: &mut Queue,
        before: Option<NodeId>,
        lines: &mut Vec<String>,
    ) {
        while let Some((p, plan, k)) = queue.next_due(before) {
            self.lane(p, plan, k, lines);
        }
    }

    /// `double dq5[8];` and the loop writing it.
    fn lane(&self, p: usize, plan: &Tangents, k: usize, lines: &mut Vec<String>) {
        let (ty, count) = (self.precision.c_type(), width(plan.directions));
        let name = lane_text(p, k);
        let terms = &plan.lanes[k].terms;
        let (units, vectors): (Vec<&Term>, Vec<&Term>) =
            terms.iter().partition(|t| matches!(t.of, Of::Unit(_)));
        lines.push(format!("{ty} {name}[{count}];"));
        // Each direction's units as a row of the identity times their sum: an array of them
        // built from scalars would be written to the stack value by value and read back as
        // one vector, which waits for the stores.
        let unit = super::unit_table(plan.directions, self.precision);
        let mut acc: Option<String> = None;
        for j in 0..plan.directions {
            let at: Vec<&&Term> = units
                .iter()
                .filter(|t| t.of == Of::Unit(direction(j)))
                .collect();
            if at.is_empty() {
                continue;
            }
            let sum = self.unit_sum(at.into_iter());
            let e = format!("{unit}[{j}][k_]");
            acc = Some(match acc {
                None => format!("{e} * ({sum})"),
                Some(a) => format!("{}({e}, {sum}, {a})", self.precision.fma()),
            });
        }
        // A term twice (the tangent of a square, `2 a da`) is taken once, its factor times two.
        let mut counted: Vec<(&Term, usize)> = Vec::new();
        for t in vectors {
            match counted.iter_mut().find(|(u, _)| *u == t) {
                Some((_, n)) => *n += 1,
                None => counted.push((t, 1)),
            }
        }
        for (t, n) in counted {
            let Of::Lane(l) = t.of else { continue };
            let x = format!("{}[k_]", lane_text(p, l));
            // Without factors, a negative term is subtracted (or negated, first).
            let signed = t.negative && (!t.factors.is_empty() || n > 1);
            let factor = match (self.product(&t.factors, signed), n) {
                (f, 1) => f,
                (Some(f), n) => Some(format!("{f} * {}", self.precision.literal(n as f64))),
                (None, n) => Some(self.precision.literal(n as f64)),
            };
            acc = Some(match (acc, factor) {
                (None, None) if t.negative => format!("-{x}"),
                (None, None) => x,
                (None, Some(f)) => format!("{x} * {f}"),
                (Some(a), None) if t.negative => format!("{a} - {x}"),
                (Some(a), None) => format!("{a} + {x}"),
                (Some(a), Some(f)) => format!("{}({x}, {f}, {a})", self.precision.fma()),
            });
        }
        let value = acc.unwrap_or_else(|| self.precision.literal(0.0));
        lines.push(format!(
            "for (int k_ = 0; k_ < {count}; ++k_) {name}[k_] = {value};"
        ));
    }

    /// One value of a sum of unit vectors: the sum of its terms' signed products.
    fn unit_sum<'t>(&self, terms: impl Iterator<Item = &'t &'t Term>) -> String {
        let mut sum: Option<String> = None;
        for t in terms {
            let value = self
                .product(&t.factors, false)
                .unwrap_or_else(|| self.precision.literal(1.0));
            sum = Some(match (sum, t.negative) {
                (None, false) => value,
                (None, true) => format!("-{value}"),
                (Some(s), false) => format!("{s} + {value}"),
                (Some(s), true) => format!("{s} - {value}"),
            });
        }
        sum.unwrap_or_else(|| self.precision.literal(0.0))
    }

    /// `f1 * f2 ...` (each factor bound, read by name), negated if `negative`, or `None` for
    /// no factor and positive.
    fn product(&self, factors: &[NodeId], negative: bool) -> Option<String> {
        let product = factors
            .iter()
            .map(|&f| self.expr(f, Place::MulRight))
            .reduce(|p, e| format!("{p} * {e}"));
        match (product, negative) {
            (None, false) => None,
            (None, true) => Some(format!("-{}", self.precision.literal(1.0))),
            (Some(p), false) => Some(p),
            (Some(p), true) => Some(format!("(-({p}))")),
        }
    }

    /// `dtau[0][2][j] = dq7[j];` for each row of a planned matrix (zeros where a row is
    /// zero), `to` the matrix in its array (`dtau[0]`).
    pub(super) fn lane_rows(&self, to: &str, p: usize, plan: &Tangents) -> Vec<String> {
        let zero = self.precision.literal(0.0);
        let mut lines = Vec::new();
        for (i, lane) in plan.outputs.iter().enumerate() {
            for j in 0..plan.directions {
                let value =
                    lane.map_or_else(|| zero.clone(), |l| format!("{}[{j}]", lane_text(p, l)));
                lines.push(format!("{to}[{i}][{j}] = {value};"));
            }
        }
        lines
    }
}

/// Direction `j` as a unit vector's index.
fn direction(j: usize) -> u16 {
    u16::try_from(j).unwrap_or(u16::MAX)
}
