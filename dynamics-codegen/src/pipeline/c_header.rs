//! The door's C header: a loaded robot's equations as one header-only C file, with each
//! function's signature for the bindings that compile and call it (the Python package), as
//! `dynamics emit --lang c` writes it.

use super::{Diagnostic, Loaded};
use crate::emit_c::{self, Function};
use crate::identifiers::c_prefix_problem;
use crate::method::{Family, FamilySet};
use crate::model::Simplification;

/// What a floating base's C header holds beyond the method table's functions
/// (`dynamics emit --lang c --floating --kinematics --contacts --configuration`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FloatingC {
    /// The kinematics: the centre of mass, centroidal momentum, the frames' poses, Jacobians
    /// and `J̇ v`.
    pub kinematics: bool,
    /// The contacts (with the kinematics): the contact terms in closed form, the constrained
    /// forward dynamics, the dynamics with given wrenches.
    pub contacts: bool,
    /// `integrate` and `difference`.
    pub configuration: bool,
}

impl FloatingC {
    /// The command line's options that ask for them, for the header's first line.
    fn options(self) -> String {
        let mut options = String::new();
        for (asked, option) in [
            (self.kinematics, " --kinematics"),
            (self.contacts, " --contacts"),
            (self.configuration, " --configuration"),
        ] {
            if asked {
                options.push_str(option);
            }
        }
        options
    }
}

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
    /// The frames of a floating base's kinematics and contacts, where the header has them
    /// (`FloatingC`), in the order of their results; else none.
    pub frames: Vec<String>,
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
        Ok(self.header_of(&eq, families, prefix, None))
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
        self.floating_c_header_with(families, FloatingC::default(), prefix)
    }

    /// [`Loaded::floating_c_header`] with the functions beyond the method table's that `extra`
    /// asks for (the kinematics, the contacts, the configuration space:
    /// [`emit_c::FloatingExtras`]), traced after the table's families, so that the table's
    /// functions are the same text with or without them.
    ///
    /// # Errors
    /// As [`Loaded::floating_c_header`].
    pub fn floating_c_header_with(
        &self,
        families: FamilySet,
        extra: FloatingC,
        prefix: Option<&str>,
    ) -> Result<CHeader, Vec<Diagnostic>> {
        if let Some(problem) = prefix.and_then(c_prefix_problem) {
            return Err(vec![Diagnostic::of_caller(format!("prefix: {problem}"))]);
        }
        let mut eq = self.floating_equations_with(families)?;
        let flyer = self.flyer.as_ref().map_err(Clone::clone)?;
        // The contacts read the frames' Jacobians.
        let kinematics = (extra.kinematics || extra.contacts)
            .then(|| eq.floating_kinematics(&self.floating_frames_robot(), flyer));
        let contacts = match (&kinematics, extra.contacts) {
            (Some(k), true) => Some(eq.floating_contacts(k)),
            _ => None,
        };
        let extras = emit_c::FloatingExtras {
            kinematics: kinematics.as_ref(),
            contacts: contacts.as_ref(),
            configuration: extra.configuration,
        };
        Ok(self.header_of(&eq, families, prefix, Some((&extras, extra))))
    }

    /// The header of `eq`, these equations of the robot (on a free-flying base where
    /// `floating` gives its extras and the options that asked for them).
    fn header_of(
        &self,
        eq: &crate::trace::Equations,
        families: FamilySet,
        prefix: Option<&str>,
        floating: Option<(&emit_c::FloatingExtras, FloatingC)>,
    ) -> CHeader {
        let name = &self.robot.name;
        let mut command = self.emit_command(families, prefix, floating.is_some());
        command.push_str(&floating.map_or_else(String::new, |(_, asked)| asked.options()));
        let prefix = prefix.map_or_else(|| emit_c::prefix(name), str::to_owned);
        let extras = floating.map_or_else(emit_c::FloatingExtras::default, |(e, _)| *e);
        CHeader {
            frames: extras
                .kinematics
                .map_or_else(Vec::new, |k| k.frame_names.clone()),
            floating: floating.is_some(),
            text: emit_c::header_with(eq, &extras, name, &prefix, &command),
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
