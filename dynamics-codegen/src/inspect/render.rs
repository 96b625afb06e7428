//! The whole printout of an [`Inspection`]: a header naming the notation, then each section
//! with its equations (LaTeX in `align*` environments), or a note where a section did not
//! fit the limits.

use super::branches;
use super::label::{Label, Quantity};
use super::print::{Format, Printer};
use super::sections::{Entry, Section};
use super::{Inspection, KinematicPart};
use std::fmt::Write;

impl Inspection {
    /// The equations in `format`.
    #[must_use]
    pub fn render(&self, format: Format) -> String {
        let p = Printer {
            format,
            kinds: &self.kinds,
            factors_first: self.kinematics,
            floating: self.floating,
        };
        let mut out = self.header(&p);
        for section in &self.sections {
            self.render_section(&p, section, &mut out);
        }
        out
    }

    /// One part of the kinematics ([`inspect_kinematics`](super::inspect_kinematics)): the
    /// notation, then its section; `None` for the equations of motion.
    #[must_use]
    pub fn render_part(&self, part: KinematicPart, format: Format) -> Option<String> {
        let quantity = match part {
            KinematicPart::HandPose => Quantity::HandPose,
            KinematicPart::JacobianInBase => Quantity::JacobianInBase,
            KinematicPart::JacobianInHand => Quantity::JacobianInHand,
        };
        let section = self.sections.iter().find(|s| s.quantity == quantity)?;
        let p = Printer {
            format,
            kinds: &self.kinds,
            factors_first: self.kinematics,
            floating: self.floating,
        };
        let mut out = self.header(&p);
        self.render_section(&p, section, &mut out);
        Some(out)
    }

    /// The robot's name, its joint variables and the notation.
    fn header(&self, p: &Printer<'_>) -> String {
        if self.floating {
            return self.floating_header(p);
        }
        let comment = if p.latex() { "% " } else { "" };
        let joints = |primes: &str| {
            let names: Vec<String> = (0..self.kinds.len())
                .map(|i| format!("{}{}{primes}", p.joint_letter(i), p.indices(&[i])))
                .collect();
            names.join(", ")
        };
        let mut out = String::new();
        let what = if self.kinematics {
            "hand pose and Jacobians"
        } else {
            "equations of motion"
        };
        let _ = writeln!(
            out,
            "{comment}{}: {what} in the notation of Niku, Introduction to Robotics, ch. 6",
            self.name
        );
        let mut variables = joints("");
        if !p.latex() && !self.kinematics {
            // Primes, not the book's dots (see `print`): named here, as the book never does.
            let _ = write!(
                variables,
                "; velocities {}; accelerations {}",
                joints("'"),
                joints("''")
            );
        }
        let _ = writeln!(out, "{comment}joint variables {variables}");
        if let Some(antecedents) = &self.antecedents {
            self.tree_lines(p, antecedents, &mut out);
        }
        let _ = writeln!(
            out,
            "{comment}Si = sin θi, Ci = cos θi, S12 = sin(θ1 + θ2), C12 = cos(θ1 + θ2), …"
        );
        if self.offsets {
            let _ = writeln!(
                out,
                "{comment}θi in Si, Ci includes the joint's constant offset where it is not a multiple of 90°"
            );
        }
        if self.mimics {
            let _ = writeln!(
                out,
                "{comment}a mimic joint follows joint j: sin(k qj + c), cos(k qj + c) are its sine and cosine, \
                 k its multiplier, qj joint j's variable without its constant offset, c the mimic's offset plus its own constant offset"
            );
        }
        out
    }

    /// A tree's branches, and the entries of `D` its branches make zero (left out below).
    fn tree_lines(&self, p: &Printer<'_>, antecedents: &[Option<usize>], out: &mut String) {
        let comment = if p.latex() { "% " } else { "" };
        let _ = writeln!(
            out,
            "{comment}a tree (Khalil-Kleinfinger's antecedents): {}",
            branches::describe(antecedents)
        );
        let zeros = branches::zero_inertia(antecedents);
        if self.kinematics || zeros.is_empty() {
            return;
        }
        let zeros: Vec<String> = zeros
            .iter()
            .map(|&(i, j)| Label::new(Quantity::Inertia, &[i, j]).render(p))
            .collect();
        let _ = writeln!(
            out,
            "{comment}zero, as their joints are on different branches (left out below): {}",
            zeros.join(", ")
        );
    }

    fn render_section(&self, p: &Printer<'_>, section: &Section, out: &mut String) {
        let title = section.quantity.heading();
        out.push('\n');
        if p.latex() {
            let _ = writeln!(out, "% {title}\n\\begin{{align*}}");
        } else {
            let _ = writeln!(out, "{title}:");
        }
        if section.entries.iter().any(|e| e.value.is_none()) {
            let command = if self.kinematics {
                "dynamics inspect --kinematics"
            } else {
                "dynamics inspect"
            };
            let (terms, work) = (self.limits.max_terms, self.limits.max_work);
            let msg = if self.floating {
                // The command's own bound (`FLOATING_LIMITS`): nothing else prints more.
                format!("too large to print (over {terms} terms or {work} term operations in all)")
            } else {
                format!(
                    "too large to print here (over {terms} terms or {work} term operations): the `{command}` command prints it"
                )
            };
            if p.latex() {
                let _ = writeln!(out, "&\\text{{{msg}}}");
            } else {
                let _ = writeln!(out, "  {msg}");
            }
        } else {
            let last = section.entries.len().saturating_sub(1);
            for (k, entry) in section.entries.iter().enumerate() {
                out.push_str(&equation(p, entry, k == last));
            }
        }
        if p.latex() {
            let _ = writeln!(out, "\\end{{align*}}");
        }
    }
}

/// One line `D12 = D21 = …`; in LaTeX, a row of `align*`, ended by `\\` unless `last`.
fn equation(p: &Printer<'_>, entry: &Entry, last: bool) -> String {
    let names: Vec<String> = entry.labels.iter().map(|l| l.render(p)).collect();
    let names = names.join(" = ");
    let value = entry.value.as_deref().unwrap_or(&[]);
    if p.latex() {
        let end = if last { "" } else { " \\\\" };
        format!("{names} &= {}{end}\n", p.latex_lines(value))
    } else {
        format!("  {names} = {}\n", p.sum(value))
    }
}
