//! Where a `Robot`'s description comes from, as Python gives it: the file, a URDF's chain or
//! branches,
//! a description file's hand frame; loaded through the front door.

use dynamics_codegen::pipeline::{self, Diagnostic, Loaded, Source};
use dynamics_codegen::Chain;

/// A robot's description, as `Robot.from_file` and `Robot.from_urdf` name it.
pub struct Described {
    /// The file's path, as the user gave it.
    pub path: String,
    /// A URDF's first link.
    pub base: Option<String>,
    /// A URDF's last link, of a chain.
    pub tip: Option<String>,
    /// The links a URDF's branches kept lead to (empty: every branch).
    pub tips: Vec<String>,
    /// A description file's hand frame `[x, y, z, roll, pitch, yaw]`.
    pub tool: Option<[f64; 6]>,
    /// Whether each link's inertia is checked (`check_inertia=False`: published data kept as
    /// given).
    pub check_inertia: bool,
}

impl Described {
    /// The robot read and checked, with its tool.
    ///
    /// # Errors
    /// The description's problems, each at its place, or the arguments' (no file).
    pub fn load(&self) -> Result<Loaded, Vec<Diagnostic>> {
        let tips: Vec<&str> = self.tips.iter().map(String::as_str).collect();
        let source = Source {
            path: &self.path,
            text: None,
            chain: Chain {
                base: self.base.as_deref(),
                tip: self.tip.as_deref(),
                tips: &tips,
            },
            check_inertia: self.check_inertia,
        };
        let names_links = self.base.is_some() || self.tip.is_some() || !tips.is_empty();
        if !source.is_urdf() && names_links {
            let message = format!(
                "base, tip and tips name links of a URDF file; `{}` is not one (*.urdf)",
                self.path
            );
            return Err(vec![caller(message, None)]);
        }
        let loaded = pipeline::load(&source)?;
        match self.tool {
            Some(tool) => loaded.with_tool(tool).map_err(|message| {
                let help = source
                    .is_urdf()
                    .then(|| "choose the hand with `tip`".to_owned());
                vec![caller(format!("tool: {message}"), help)]
            }),
            None => Ok(loaded),
        }
    }
}

/// A mistake in the argument `name`: its diagnostic, the argument named first.
pub fn argument(name: &str, d: Diagnostic) -> Diagnostic {
    Diagnostic {
        message: format!("{name}: {}", d.message),
        ..d
    }
}

/// A mistake in the arguments, with no file.
fn caller(message: String, help: Option<String>) -> Diagnostic {
    Diagnostic {
        file: None,
        line: None,
        column: None,
        message,
        help,
    }
}
