//! The front door: the generator's pipeline as a few calls, for every driver of a description
//! file (the commands, the benchmarks, Python). The derive enters through
//! [`crate::derive_dynamics`], whose attributes are read by its own front end; from the
//! checked robot on, both take the same path (`equations` below).
//!
//! ```text
//! load(source)          front (a TOML or JSON description, a URDF) → check: a checked Robot
//!   .simplification(..) the file's [simplify] with the caller's overrides, resolved
//!   .equations(..)      trace → the opt-in families → simplify: the Equations to emit
//!     .evaluate(state)  every node at one state, in f64 (what `dynamics eval` prints)
//! ```
//!
//! Errors are data: a [`Diagnostic`] holds the file, line and column of a problem and its
//! message, printed one way (`file:line:col: message`).

use crate::check;
use crate::front::{self, Chain, FileRequest, RequestError};
use crate::method::{Family, FamilySet};
use crate::model::{FreeFlyer, Placement, Robot, Simplification, Value};
use crate::trace::{self, Equations};

mod c_header;
mod diagnostic;
mod evaluate;
mod families;
mod floating;
mod readable;
mod rust_module;

/// A C function's signature, as the header declares it.
pub use crate::emit_c::{Function, Precision, Returns};
/// A URDF joint's `<limit>`.
pub use crate::front::Limit;
/// The readable equations' notation: text or LaTeX.
pub use crate::inspect::Format;
/// The equations' graph, its leaves, and its outputs compiled to a tape that evaluates many
/// states on any scalar (lanes of four, tangents): for drivers that evaluate outputs at run time.
pub use crate::symbolic::{Graph, NodeId, Tape, TapeScalar, Var};
pub use c_header::{CHeader, FloatingC};
pub use diagnostic::Diagnostic;
pub use evaluate::{State, Values};
pub use families::{asked_by_name, families, opt_in_family};
pub(crate) use floating::expand_floating;
pub use readable::{derived_readable, DerivedReadable, Readable};
pub use rust_module::RustModule;

/// Where a robot's description comes from.
#[derive(Clone, Copy, Debug)]
pub struct Source<'a> {
    /// The file's path as the user wrote it (messages name it); `*.urdf` is read as a URDF,
    /// `*.toml` and `*.json` as description files.
    pub path: &'a str,
    /// The file's text, or `None` to read it from `path`.
    pub text: Option<&'a str>,
    /// A URDF's joints: its base link, and the tip of a chain or the tips of the branches kept
    /// (by default the root link and every branch).
    pub chain: Chain<'a>,
    /// Whether each link's inertia is checked (by default); `false` is the derive's
    /// `check_inertia = false`, for published data whose moments break the triangle inequality.
    pub check_inertia: bool,
}

impl Default for Source<'_> {
    fn default() -> Self {
        Source {
            path: "",
            text: None,
            chain: Chain::default(),
            check_inertia: true,
        }
    }
}

impl<'a> Source<'a> {
    /// The command line's options that choose what this source loads.
    fn options(&self) -> Vec<String> {
        let Chain { base, tip, tips } = self.chain;
        let mut options: Vec<String> = [("--base", base), ("--tip", tip)]
            .into_iter()
            .filter_map(|(option, link)| link.map(|link| format!("{option} {link}")))
            .collect();
        if !tips.is_empty() {
            options.push(format!("--tips {}", tips.join(",")));
        }
        if !self.check_inertia {
            options.push("--no-check-inertia".to_owned());
        }
        options
    }

    /// The file at `path`, read when loaded.
    #[must_use]
    pub fn file(path: &'a str) -> Source<'a> {
        Source {
            path,
            ..Source::default()
        }
    }

    /// Its text: as given, or read from its path.
    fn read(&self) -> Result<std::borrow::Cow<'a, str>, Vec<Diagnostic>> {
        match self.text {
            Some(text) => Ok(text.into()),
            None => std::fs::read_to_string(self.path)
                .map(Into::into)
                .map_err(|e| vec![Diagnostic::of_file(self.path, e.to_string())]),
        }
    }

    /// Whether it is a URDF file.
    #[must_use]
    pub fn is_urdf(&self) -> bool {
        self.path.ends_with(".urdf")
    }
}

/// A robot read and checked as the derive reads it, with what its file asks of the
/// simplified models.
pub struct Loaded {
    /// The robot.
    pub robot: Robot,
    /// The file's path, as given.
    pub path: String,
    /// The command line's options that load the robot again as loaded (`--tips a,b`,
    /// `--no-check-inertia`, `--tool ..`): the generated files name the command that writes
    /// them.
    pub options: Vec<String>,
    is_urdf: bool,
    request: FileRequest,
    /// The body it flies on if its base floats: a URDF's root link (or `chain.base`) and the
    /// links fixed to it, a description file's `[floating]`; else why it has none.
    flyer: Result<FreeFlyer, Vec<Diagnostic>>,
    /// A URDF loaded without named tips: its text, base link and inertia check, from which
    /// [`Loaded::floating_frames_robot`] loads it again with its moving leaves as tips.
    urdf: Option<(String, Option<String>, bool)>,
}

/// Reads the description of `source` and checks it as the derive does (values, then the
/// physical checks of each link and the joint count).
///
/// # Errors
/// Every problem found, each with its file, line and column where it has them.
pub fn load(source: &Source<'_>) -> Result<Loaded, Vec<Diagnostic>> {
    let path = source.path;
    let text = source.read()?;
    let text = text.as_ref();
    let (loaded, limits) = if source.is_urdf() {
        let loaded =
            front::load_urdf(path, text, source.chain, source.check_inertia).map_err(|errors| {
                let each = errors.iter().map(|e| Diagnostic::from_file_error(path, e));
                each.collect::<Vec<_>>()
            })?;
        (loaded, front::joint_limits(text, source.chain).ok())
    } else {
        let mut loaded =
            front::load(path, text).map_err(|e| vec![Diagnostic::from_file_error(path, &e)])?;
        for checked in &mut loaded.check_inertia {
            *checked &= source.check_inertia;
        }
        (loaded, None)
    };
    let problems: Vec<Diagnostic> = check::robot(&loaded.robot, &loaded.check_inertia)
        .iter()
        .map(|problem| {
            let at = loaded.sources.place(problem).copied();
            Diagnostic::at(path, at, problem.to_string())
        })
        .collect();
    if !problems.is_empty() {
        return Err(problems);
    }
    let flyer = if source.is_urdf() {
        front::free_flyer(text, source.chain.base).map_err(|errors| {
            let each = errors.iter().map(|e| Diagnostic::from_file_error(path, e));
            each.collect()
        })
    } else {
        let message = "no `[floating]` table: the floating body (`mass`, `com`, `inertia` in the \
                       base frame, as a joint's)";
        (loaded.floating.clone()).ok_or_else(|| vec![Diagnostic::of_file(path, message)])
    };
    Ok(Loaded {
        robot: loaded.robot,
        path: path.to_owned(),
        options: source.options(),
        is_urdf: source.is_urdf(),
        request: FileRequest {
            given: loaded.simplify,
            limits,
            path: path.to_owned(),
        },
        flyer,
        urdf: (source.is_urdf() && source.chain.tip.is_none() && source.chain.tips.is_empty())
            .then(|| {
                let base = source.chain.base.map(str::to_owned);
                (text.to_owned(), base, source.check_inertia)
            }),
    })
}

impl Loaded {
    /// The robot with its hand frame at `[x, y, z, roll, pitch, yaw]` in the last link's frame.
    ///
    /// # Errors
    /// A URDF, whose hand frame is its tip link, or a description that declares its own tool
    /// (which this would override unseen): the message says which.
    pub fn with_tool(mut self, tool: [f64; 6]) -> Result<Loaded, String> {
        let path = &self.path;
        if self.is_urdf {
            return Err(format!("the hand frame of `{path}` is its tip link"));
        }
        if self.robot.tool.is_some() {
            return Err(format!("`{path}` declares a `tool` already"));
        }
        let numbers: Vec<String> = tool.iter().map(f64::to_string).collect();
        self.options.push(format!("--tool {}", numbers.join(",")));
        let [x, y, z, roll, pitch, yaw] = tool.map(Value::from_f64);
        self.robot.tool = Some(Placement {
            xyz: [x, y, z],
            rpy: [roll, pitch, yaw],
        });
        Ok(self)
    }

    /// The equations of the robot on a free-flying base (`base = floating` in the derive): M, h,
    /// τ, g, the forward dynamics and M⁻¹, as the derive traces them.
    ///
    /// # Errors
    /// A description file without a `[floating]` table, a URDF whose body cannot be read, or
    /// what a floating base does not support yet (joint springs). A robot with mimic joints
    /// has them in its coordinates.
    pub fn floating_equations(&self) -> Result<Equations, Vec<Diagnostic>> {
        let flyer = self.floating_flyer()?;
        Ok(crate::trace::derive_floating(&self.robot, flyer))
    }

    /// The robot whose tip frames are a floating base's frames as the derive has them: a URDF
    /// loaded without named tips again with its moving leaves as tips (the derive's
    /// `front::floating_frames`: Solo 12's feet, links fixed below its lower legs), else the
    /// robot as loaded. The same joints in the same order: only its tips differ.
    pub(crate) fn floating_frames_robot(&self) -> std::borrow::Cow<'_, Robot> {
        let Some((text, base, check_inertia)) = &self.urdf else {
            return std::borrow::Cow::Borrowed(&self.robot);
        };
        let leaves = front::urdf::moving_leaves(text, base.as_deref());
        let tips: Vec<&str> = leaves.iter().map(String::as_str).collect();
        let chain = front::Chain {
            base: base.as_deref(),
            tip: None,
            tips: &tips,
        };
        match front::load_urdf(&self.path, text, chain, *check_inertia) {
            Ok(loaded) if !tips.is_empty() => std::borrow::Cow::Owned(loaded.robot),
            _ => std::borrow::Cow::Borrowed(&self.robot),
        }
    }

    /// The body the robot flies on, where a floating base supports the robot.
    fn floating_flyer(&self) -> Result<&FreeFlyer, Vec<Diagnostic>> {
        let flyer = self.flyer.as_ref().map_err(Clone::clone)?;
        let unsupported = front::floating_unsupported(&self.robot);
        if !unsupported.is_empty() {
            let each = unsupported
                .into_iter()
                .map(|m| Diagnostic::of_file(&self.path, m));
            return Err(each.collect());
        }
        Ok(flyer)
    }

    /// The frames' kinematics traced into `eq` ([`Loaded::floating_equations`]'), then the
    /// contact terms of every frame (`FloatingContactTerms`), as the derive traces them; the
    /// wall-clock time of the contact terms' trace and emission, and their emitted count.
    #[must_use]
    pub fn floating_contact_terms(
        &self,
        eq: &mut Equations,
    ) -> Option<(std::time::Duration, crate::emit::OpCount)> {
        let flyer = self.flyer.as_ref().ok()?;
        let kinematics = eq.floating_kinematics(&self.robot, flyer);
        let start = std::time::Instant::now();
        let contacts = eq.floating_contacts(&kinematics);
        let ops = crate::emit::floating_contacts_count(eq, &contacts);
        Some((start.elapsed(), ops))
    }

    /// [`Loaded::floating_equations`] with the opt-in families of `families` traced, as the
    /// derive traces them (`derivatives`, `regressor`, `base_parameters`).
    ///
    /// # Errors
    /// As [`Loaded::floating_equations`], where the base parameters cannot be traced (a
    /// length or angle given by a struct field), and the regressor or base parameters beside
    /// joint friction or actuator inertia (no columns for them yet).
    pub fn floating_equations_with(
        &self,
        families: FamilySet,
    ) -> Result<Equations, Vec<Diagnostic>> {
        let refused: Vec<Diagnostic> = Family::ALL
            .iter()
            .filter(|&&f| families.contains(f))
            .filter_map(|&f| front::floating_joint_terms_refusal(&self.robot, f))
            .map(|m| Diagnostic::of_file(&self.path, m))
            .collect();
        if !refused.is_empty() {
            return Err(refused);
        }
        let mut eq = self.floating_equations()?;
        let flyer = self.flyer.as_ref().map_err(Clone::clone)?;
        if floating::add_floating_families(&mut eq, &self.robot, flyer, families) {
            return Ok(eq);
        }
        let message = "the base parameters need the robot's lengths and angles as numbers";
        Err(vec![Diagnostic::of_file(&self.path, message)])
    }

    /// Whether the file has a `[simplify]` table of its own.
    #[must_use]
    pub fn asks_simplified(&self) -> bool {
        self.request.given.is_some()
    }

    /// The simplified models the file asks for (its `[simplify]`, a URDF's `<limit>`s as the
    /// defaults), each key of `overrides` (a key of `simplify(...)` and its values, one for
    /// every joint or one per joint) in place of the file's; `None` where neither asks.
    ///
    /// # Errors
    /// Every mistake, each placed: in the file, or in the overrides (`in_file` false).
    pub fn simplification(
        &self,
        overrides: &[(&'static str, Vec<f64>)],
    ) -> Result<Option<Simplification>, Vec<RequestError>> {
        self.request.resolve(&self.robot, overrides)
    }

    /// The robot's equations: every family the derive always generates, the opt-in ones of
    /// `families`, and the simplified models of `simplification` (which ask for their
    /// family), as the derive builds them.
    ///
    /// # Errors
    /// Simplified models that cannot be built (`file: simplify: ...`).
    pub fn equations(
        &self,
        families: FamilySet,
        simplification: Option<&Simplification>,
    ) -> Result<Equations, Diagnostic> {
        let (eq, simplified) = equations(&self.robot, families, simplification);
        match simplified {
            Some(Err(e)) => Err(Diagnostic::of_file(&self.path, format!("simplify: {e}"))),
            _ => Ok(eq),
        }
    }
}

/// A URDF's `<limit>`s, one per joint of the chain of `source` (which must be a URDF).
///
/// # Errors
/// The file's problems, each at its place.
pub fn joint_limits(source: &Source<'_>) -> Result<Vec<Limit>, Vec<Diagnostic>> {
    let path = source.path;
    let text = source.read()?;
    let text = text.as_ref();
    front::joint_limits(text, source.chain).map_err(|errors| {
        let each = errors.iter().map(|e| Diagnostic::from_file_error(path, e));
        each.collect()
    })
}

/// The checks [`load`] runs, on a robot the caller has changed since (parameters given values
/// from outside): each problem's message, base to tip. The links' inertia tensors are checked
/// where `check_inertia` is true.
#[must_use]
pub fn problems(robot: &Robot, check_inertia: bool) -> Vec<String> {
    let checked = vec![check_inertia; robot.joints.len()];
    check::robot(robot, &checked)
        .iter()
        .map(ToString::to_string)
        .collect()
}

/// trace → the opt-in families → simplify: the one spelling of the pipeline's second half, for
/// the derive and [`Loaded::equations`]. The simplified models' outcome beside the equations,
/// which the derive still expands when they fail (with the error in place of their methods).
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn equations(
    robot: &Robot,
    families: FamilySet,
    simplification: Option<&Simplification>,
) -> (Equations, Option<Result<(), String>>) {
    let mut eq = trace::derive(robot);
    eq.add_families(robot, families);
    // Only for a robot that asks: the expansion costs what the rest of the derive does.
    let simplified = simplification.map(|request| crate::simplify::add(&mut eq, request));
    (eq, simplified)
}
