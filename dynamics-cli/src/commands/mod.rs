//! One module per subcommand; what they share: reading the description file, the names the
//! generated code uses, usage errors, writing a figure ([`values`]: the options' values checked
//! against the robot).

mod emit;
mod eval;
mod excite;
mod identify;
mod inspect;
mod simulate;
mod simulate_batch;
mod size;
mod stats;
mod values;

use crate::args::{Cli, Command, RobotFile};
use crate::plot;
use clap::error::ErrorKind;
use clap::CommandFactory;
use dynamics_codegen::model::{Robot, Simplification};
use dynamics_codegen::{rust_field, rust_type, Chain, Equations, Loaded, Source, SIMPLIFY_KEYS};
use proc_macro2::{Span, TokenStream};
use quote::quote;
use std::io::BufWriter;

/// Why a command failed.
pub enum Failure {
    /// A usage error found after parsing (a list of the wrong length, a missing parameter):
    /// reported as clap reports its own, exit code 2.
    Usage(clap::Error),
    /// The description file cannot be read or fails the checks: `file:line:col: message`
    /// lines, exit code 1.
    File(String),
}

/// Runs `command`; what it prints.
pub fn run(command: &Command) -> Result<String, Failure> {
    match command {
        Command::Inspect(args) => inspect::run(args),
        Command::Emit(args) => emit::run(args),
        Command::Stats(args) => stats::run(args),
        Command::Eval(args) => eval::run(args),
        Command::Size(args) => size::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Identify(args) => identify::run(args),
        Command::Excite(args) => excite::run(args),
    }
}

/// Reads and checks a description file as the derive does (values, then the physical checks
/// of each link and the joint count); errors carry `file:line:col`. A `.urdf` file is read
/// with its `--base` and `--tip`.
fn load(robot: &RobotFile) -> Result<Robot, Failure> {
    load_with_request(robot).map(|loaded| loaded.robot)
}

/// [`load`], with what the file asks of the simplified models (its `[simplify]`, a URDF's
/// `<limit>`s), as the derive reads them for `file = ".."` or `urdf = ".."`.
fn load_with_request(robot: &RobotFile) -> Result<Loaded, Failure> {
    let path = robot.path.as_str();
    let tips: Vec<&str> = robot.tips.iter().map(String::as_str).collect();
    let source = Source {
        path,
        text: None,
        chain: Chain {
            base: robot.base.as_deref(),
            tip: robot.tip.as_deref(),
            tips: &tips,
        },
        check_inertia: !robot.no_check_inertia,
    };
    let names_links = robot.base.is_some() || robot.tip.is_some() || !tips.is_empty();
    if !source.is_urdf() && names_links {
        let message = format!(
            "--base, --tip and --tips name links of a URDF file; `{path}` is not one (*.urdf)"
        );
        return Err(Failure::Usage(
            Cli::command().error(ErrorKind::ArgumentConflict, message),
        ));
    }
    let mut loaded = dynamics_codegen::load(&source).map_err(|diagnostics| {
        let lines: Vec<String> = diagnostics.iter().map(ToString::to_string).collect();
        Failure::File(lines.join("\ndynamics: "))
    })?;
    if let Some(tool) = &robot.tool {
        loaded = loaded.with_tool(tool.0).map_err(|message| {
            let message = if source.is_urdf() {
                format!("--tool: {message}; choose it with --tip")
            } else {
                format!("--tool: {message}")
            };
            Failure::Usage(Cli::command().error(ErrorKind::ArgumentConflict, message))
        })?;
    }
    Ok(loaded)
}

/// The simplified models of `robot` that the file's `request` asks for, each key of
/// `overrides` (the command line's) in place of the file's; `None` where neither asks. A
/// mistake of the file's is a file error, one of the command line's a usage error of
/// `command`.
fn simplification(
    loaded: &Loaded,
    overrides: &[(&'static str, Vec<f64>)],
    command: &str,
) -> Result<Option<Simplification>, Failure> {
    loaded.simplification(overrides).map_err(|problems| {
        match problems.iter().find(|p| !p.in_file) {
            // The command line's options as the user wrote them, not the file's keys.
            Some(p) => {
                let mut message = p.problem.clone();
                for key in SIMPLIFY_KEYS {
                    let option = format!("--{}", key.replace('_', "-"));
                    message = message.replace(&format!("`{key}`"), &option);
                }
                usage(command, &message)
            }
            None => {
                let lines: Vec<String> = problems.iter().map(ToString::to_string).collect();
                Failure::File(lines.join("\ndynamics: "))
            }
        }
    })
}

/// `two_link` → `TwoLink`: the name of the struct the generated code implements `Dynamics` for
/// (`Robot` before a name Rust could not take: `RobotSelf`, `Robot1arm`).
fn type_name(name: &str) -> syn::Ident {
    syn::Ident::new(&rust_type(name), Span::call_site())
}

/// The struct's fields, one per parameter, as the generated code reads them: `self.m1`, ...,
/// `self.r#type` for a keyword; the error of a name no field can have (which the value grammar
/// of the description file at `path` refuses first).
fn field_idents(eq: &Equations, path: &str) -> Result<Vec<syn::Ident>, Failure> {
    eq.fields
        .iter()
        .map(|f| rust_field(f).map_err(|e| Failure::File(format!("{path}: {e}"))))
        .collect()
}

fn self_fields(idents: &[syn::Ident]) -> Vec<TokenStream> {
    idents.iter().map(|i| quote!(self.#i)).collect()
}

/// A usage error of `command` found once the robot is known, reported as clap reports its own.
pub(crate) fn usage(command: &str, message: &str) -> Failure {
    let mut cli = Cli::command();
    cli.build();
    let error = match cli.find_subcommand_mut(command) {
        Some(eval) => eval.error(ErrorKind::ValueValidation, message),
        None => cli.error(ErrorKind::ValueValidation, message),
    };
    Failure::Usage(error)
}

/// Writes `figure` as SVG to the file at `path`.
pub(super) fn write_svg(path: &str, figure: &plot::Figure<'_>) -> Result<(), Failure> {
    let failed = |e: std::io::Error| Failure::File(format!("{path}: {e}"));
    let file = std::fs::File::create(path).map_err(failed)?;
    let mut out = BufWriter::new(file);
    plot::write_svg(&mut out, figure).map_err(failed)?;
    std::io::Write::flush(&mut out).map_err(failed)
}

/// The error of a robot whose regressor cannot be had, from the description file at `path`.
fn robot_failure(path: &str, e: dynamics_identification::Error) -> Failure {
    match e {
        dynamics_identification::Error::StructFields => Failure::File(format!("{path}: {e}")),
        e => Failure::File(e.to_string()),
    }
}
