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
        let name = &self.robot.name;
        let command = self.emit_command(families, prefix);
        let prefix = prefix.map_or_else(|| emit_c::prefix(name), str::to_owned);
        Ok(CHeader {
            text: emit_c::header(&eq, name, &prefix, &command),
            functions: emit_c::functions(&eq, &prefix),
            dof: eq.dof,
            fields: eq.fields.clone(),
            joint_rows: eq
                .regressor
                .as_ref()
                .map_or_else(|| (0..eq.links).collect(), |r| r.rows.clone()),
            robot: name.clone(),
        })
    }

    /// The command that writes the header again: the file, the opt-in families asked for
    /// (the simplified models come from the file) and the prefix if one was given.
    fn emit_command(&self, families: FamilySet, prefix: Option<&str>) -> String {
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
        let options: String = self.options.iter().map(|o| format!(" {o}")).collect();
        format!(
            "dynamics emit --lang c {}{options}{with}{prefix}",
            self.path
        )
    }
}

#[cfg(test)]
mod tests {
    use crate::method::{Family, FamilySet};
    use crate::pipeline::{load, Diagnostic, Loaded, Source};

    /// The file at `path` from the workspace's root, named as the command line there names it.
    fn loaded(path: &str) -> Loaded {
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
        let text = std::fs::read_to_string(format!("{root}/{path}")).expect("readable");
        let source = Source {
            path,
            text: Some(&text),
            ..Source::default()
        };
        load(&source).unwrap_or_else(|e| panic!("{path}: {e:?}"))
    }

    fn golden(name: &str) -> String {
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
        std::fs::read_to_string(format!("{root}/dynamics-cli/tests/golden/{name}")).expect("golden")
    }

    /// What `dynamics emit --lang c` printed before it called this (its golden files, written
    /// by the command line's own assembly of the header): a description file's and a URDF's.
    #[test]
    fn the_header_is_the_command_lines() {
        let families = FamilySet::default();
        let puma = loaded("robots/puma560.toml");
        let header = puma.c_header(families, None, None).expect("a header");
        assert!(
            header.text == golden("puma560.h"),
            "PUMA 560's header changed"
        );
        assert_eq!((header.robot.as_str(), header.dof), ("puma560", 6));
        assert!(header.fields.is_empty());
        let arm = loaded("dynamics-runtime/tests/ui/urdf/arm.urdf");
        let header = arm.c_header(families, None, None).expect("a header");
        assert!(
            header.text == golden("arm_urdf.h"),
            "the URDF's header changed"
        );
    }

    /// A URDF's chain, the inertia check and a tool are in the command too: without them it
    /// would write another robot's header (or none).
    #[test]
    fn the_command_keeps_the_options_that_chose_the_robot() {
        let path = "robots/urdf/trees/allegro_right_hand.urdf";
        let tips = ["link_3.0_tip", "link_15.0_tip"];
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
        let text = std::fs::read_to_string(format!("{root}/{path}")).expect("readable");
        let source = Source {
            path,
            text: Some(&text),
            chain: crate::front::Chain {
                tips: &tips,
                ..Default::default()
            },
            check_inertia: false,
        };
        let hand = load(&source).expect("the hand, unchecked");
        let header = hand
            .c_header(FamilySet::default(), None, None)
            .expect("a header");
        let command = format!(
            "dynamics emit --lang c {path} --tips link_3.0_tip,link_15.0_tip --no-check-inertia`"
        );
        assert!(header.text.contains(&command), "{}", &header.text[..300]);
        let puma = loaded("robots/puma560.toml").with_tool([0.0, 0.0, 0.1, 0.0, 0.5, -1.0]);
        let header = puma
            .expect("a tool")
            .c_header(FamilySet::default(), None, None);
        let command = "dynamics emit --lang c robots/puma560.toml --tool 0,0,0.1,0,0.5,-1`";
        assert!(header.expect("a header").text.contains(command));
    }

    #[test]
    fn the_functions_signatures_and_the_command_that_writes_it_again() {
        let puma = loaded("robots/puma560.toml");
        let families = FamilySet::default().with(Family::Derivatives);
        let header = puma
            .c_header(families, None, Some("arm"))
            .expect("a header");
        let f = header
            .functions
            .iter()
            .find(|f| f.name == "arm_inverse_dynamics_derivatives")
            .expect("the derivatives, with the prefix");
        assert_eq!(f.outputs[0].dims, [2, 6, 6]);
        assert!(header.text.contains(&format!(" {}(", f.name)));
        let command = "dynamics emit --lang c robots/puma560.toml --with derivatives --prefix arm`";
        assert!(header.text.contains(command), "{}", &header.text[..300]);
        let refused = puma
            .c_header(families, None, Some("2arm"))
            .expect_err("not a C name");
        assert_eq!((refused.file, refused.line), (None, None), "the caller's");
        assert!(
            refused.message.starts_with("prefix: "),
            "{}",
            refused.message
        );
    }

    /// The simplified models a file's `[simplify]` asks for; a mistake in the table is placed
    /// at its key.
    #[test]
    fn the_files_simplified_models_and_its_mistakes_in_place() {
        let two_link = loaded("tests/data/simplify/two_link.toml");
        let asked = two_link.simplification(&[]).expect("resolves");
        let header = two_link
            .c_header(FamilySet::default(), asked.as_ref(), None)
            .expect("a header");
        assert!(header
            .functions
            .iter()
            .any(|f| f.name == "two_link_inverse_dynamics_simplified"));
        let text = "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\n\
                    a = 1\nmass = 2\n\n[simplify]\ntolerance = 1\nqd_max = -3\n";
        let source = Source {
            path: "arm.toml",
            text: Some(text),
            ..Source::default()
        };
        let arm = load(&source).expect("loads");
        let problems = arm.simplification(&[]).expect_err("a negative speed");
        let d = Diagnostic::from(&problems[0]);
        let place = (d.file.as_deref(), d.line, d.column);
        assert_eq!(place, (Some("arm.toml"), Some(11), Some(10)), "{d}");
        assert!(d.message.starts_with("simplify: "), "{d}");
        assert_eq!(d.to_string(), problems[0].to_string());
        let overridden = arm.simplification(&[("qd_max", vec![-1.0])]);
        let d = Diagnostic::from(&overridden.expect_err("the caller's")[0]);
        assert_eq!((d.file, d.line), (None, None));
    }
}
