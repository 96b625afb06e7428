//! The door's C header: a loaded robot's equations as one header-only C file, with each
//! function's signature for the bindings that compile and call it (the Python package), as
//! `dynamics emit --lang c` writes it.

use super::{Diagnostic, Loaded};
use crate::emit_c::{self, Function};
use crate::identifiers::c_prefix_problem;
use crate::method::{Family, FamilySet};
use crate::model::Simplification;

/// A robot's C header and what a binding needs to call it: its functions' signatures.
#[derive(Debug)]
pub struct CHeader {
    /// The robot's name in its description.
    pub robot: String,
    /// Its number of joints.
    pub dof: usize,
    /// Its parameters (struct fields), in the order of the functions' `params`.
    pub fields: Vec<String>,
    /// Per joint (link), the row of τ its columns of `joint_regressor` add to: the joint
    /// itself but for a mimic joint, whose row is the joint's it follows.
    pub joint_rows: Vec<usize>,
    /// Whether it is a floating base's (`base = floating`): `q` has `dof + 1` elements.
    pub floating: bool,
    /// The header's text.
    pub text: String,
    /// Its functions, in the header's order.
    pub functions: Vec<Function>,
}

impl Loaded {
    /// The C header of the robot's [`equations`](Loaded::equations) (the opt-in families of
    /// `families`, the simplified models of `simplification`), its functions named
    /// `PREFIX_method` (`prefix`, by default the robot's name in lower case, other characters
    /// than letters and digits `_`). Its first comment names the command that writes it again.
    ///
    /// # Errors
    /// A `prefix` that makes no C name (no file: the caller's), or simplified models that
    /// cannot be built (`file: simplify: ...`).
    pub fn c_header(
        &self,
        families: FamilySet,
        simplification: Option<&Simplification>,
        prefix: Option<&str>,
    ) -> Result<CHeader, Diagnostic> {
        if let Some(problem) = prefix.and_then(c_prefix_problem) {
            return Err(Diagnostic::of_caller(format!("prefix: {problem}")));
        }
        let eq = self.equations(families, simplification)?;
        Ok(self.header_of(&eq, families, prefix, false))
    }

    /// The C header of the robot on a free-flying base ([`Loaded::floating_equations_with`]
    /// the opt-in `families`), as [`Loaded::c_header`] names its functions: `FloatingDynamics`'
    /// methods, `q` of `n + 7` elements, the others `n + 6`.
    ///
    /// # Errors
    /// A `prefix` that makes no C name, and those of [`Loaded::floating_equations_with`].
    pub fn floating_c_header(
        &self,
        families: FamilySet,
        prefix: Option<&str>,
    ) -> Result<CHeader, Vec<Diagnostic>> {
        if let Some(problem) = prefix.and_then(c_prefix_problem) {
            return Err(vec![Diagnostic::of_caller(format!("prefix: {problem}"))]);
        }
        let eq = self.floating_equations_with(families)?;
        Ok(self.header_of(&eq, families, prefix, true))
    }

    /// The header of `eq`, these equations of the robot (on a free-flying base where
    /// `floating`).
    fn header_of(
        &self,
        eq: &crate::trace::Equations,
        families: FamilySet,
        prefix: Option<&str>,
        floating: bool,
    ) -> CHeader {
        let name = &self.robot.name;
        let command = self.emit_command(families, prefix, floating);
        let prefix = prefix.map_or_else(|| emit_c::prefix(name), str::to_owned);
        CHeader {
            floating,
            text: emit_c::header(eq, name, &prefix, &command),
            functions: emit_c::functions(eq, &prefix),
            dof: eq.dof,
            fields: eq.fields.clone(),
            joint_rows: eq
                .regressor
                .as_ref()
                .map_or_else(|| (0..eq.links).collect(), |r| r.rows.clone()),
            robot: name.clone(),
        }
    }

    /// The command that writes the header again: the file, the opt-in families asked for
    /// (the simplified models come from the file) and the prefix if one was given.
    fn emit_command(&self, families: FamilySet, prefix: Option<&str>, floating: bool) -> String {
        let with: Vec<&str> = families
            .opt_in()
            .filter(|&f| f != Family::Simplified)
            .map(Family::name)
            .collect();
        let with = if with.is_empty() {
            String::new()
        } else {
            format!(" --with {}", with.join(","))
        };
        let prefix = prefix.map_or_else(String::new, |prefix| format!(" --prefix {prefix}"));
        let mut options: String = self.options.iter().map(|o| format!(" {o}")).collect();
        if floating {
            options.push_str(" --floating");
        }
        format!(
            "dynamics emit --lang c {}{options}{with}{prefix}",
            self.path
        )
    }
}
