//! The printout of a [`Simplified`]: the pruned `T_i` as `dynamics inspect` prints them, then
//! the envelope and, per joint, the terms kept, the proven bound and the largest dropped terms
//! with their bounds.

use super::arrange::Term;
use super::number::decimal;
use super::print::{Format, Printer};
use super::simplified::Simplified;
use crate::simplify::Pruning;
use crate::symbolic::Number;
use std::fmt::Write;

/// The dropped terms listed per joint; the rest are counted.
const LISTED: usize = 10;

impl Simplified {
    /// The pruned torques and the report, in `format` (the report as LaTeX comments).
    #[must_use]
    pub fn render(&self, format: Format) -> String {
        let p = Printer {
            format,
            kinds: &self.inspection.kinds,
            factors_first: false,
            floating: false,
        };
        let mut out = self.inspection.render(format);
        let comment = if p.latex() { "% " } else { "" };
        let mut report = String::new();
        let _ = writeln!(
            report,
            "\nSimplified: each term's |value| bounded over the envelope by interval arithmetic; \
             the smallest dropped while their bounds sum within the tolerance, which sum bounds \
             |T_i - T_i(simplified)| (M_ij within min(t_i, t_j) / the sum of the accelerations, \
             so that (M q'')_i is within t_i)"
        );
        let _ = writeln!(report, "Envelope:");
        for (j, e) in self.envelope.joints.iter().enumerate() {
            let v = format!("{}{}", p.joint_letter(j), j + 1);
            let _ = writeln!(
                report,
                "  {v} ∈ [{}, {}], |{v}'| ≤ {}, |{v}''| ≤ {}",
                num(e.lower),
                num(e.upper),
                num(e.speed),
                num(e.acceleration)
            );
        }
        for (name, pruning) in &self.elements {
            element_report(&p, name, pruning, &mut report);
        }
        for line in report.lines() {
            let _ = writeln!(out, "{}{line}", if line.is_empty() { "" } else { comment });
        }
        out
    }
}

/// Element `t`'s counts and bounds, and its largest dropped terms.
fn element_report(p: &Printer<'_>, t: &str, pruning: &Pruning, out: &mut String) {
    let _ = writeln!(
        out,
        "\n{t}: {} of {} terms kept; |{t} - {t}(simplified)| ≤ {} (tolerance {}); |{t}| ≤ {} over the envelope",
        pruning.kept.len(),
        pruning.full.len(),
        num(pruning.bound),
        num(pruning.tolerance),
        num(pruning.magnitude)
    );
    if pruning.dropped.is_empty() {
        return;
    }
    let _ = writeln!(out, "  dropped, largest bound first (bound: term):");
    for d in pruning.dropped.iter().take(LISTED) {
        let term = Term {
            coef: d.coef,
            group: Vec::new(),
            factors: d.monomial.clone(),
        };
        let _ = writeln!(out, "    {}: {}", num(d.bound), p.sum(&[term]));
    }
    if pruning.dropped.len() > LISTED {
        let _ = writeln!(out, "    … and {} more", pruning.dropped.len() - LISTED);
    }
}

/// A float as a short decimal (6 significant digits).
fn num(x: f64) -> String {
    decimal(Number::Float(x))
}
