//! One module per subcommand; what they share: reading the description file and the names the
//! generated code uses.

mod emit;
mod eval;
mod excite;
mod identify;
mod inspect;
mod simulate;
mod simulate_batch;
mod size;
mod stats;

use crate::args::{Cli, Command, RobotFile, Tool};
use clap::error::ErrorKind;
use clap::CommandFactory;
use dynamics_codegen::check;
use dynamics_codegen::front;
use dynamics_codegen::model::{Placement, Robot, Simplification, Value};
use dynamics_codegen::trace::base_parameters::{BaseParameters, JointColumns};
use dynamics_codegen::Equations;
use proc_macro2::{Span, TokenStream};
use quote::quote;

pub use emit::{c_header, CHeader};
pub(crate) use eval::usage;

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

/// The base parameters of `robot` with the joint columns asked for (tracing its regressor into
/// `eq`), or the error of a robot whose lengths or angles are struct fields.
fn base_parameters(
    eq: &mut Equations,
    robot: &Robot,
    file: &RobotFile,
    joint_columns: &[JointColumns],
) -> Result<BaseParameters, Failure> {
    let message = "the base parameters need the robot's lengths and angles as numbers, not \
                   struct fields";
    eq.base_parameters(robot, joint_columns)
        .ok_or_else(|| Failure::File(format!("{}: {message}", file.path)))
}

/// Reads and checks a description file as the derive does (values, then the physical checks
/// of each link and the joint count); errors carry `file:line:col`. A `.urdf` file is read
/// with its `--base` and `--tip`.
fn load(robot: &RobotFile) -> Result<Robot, Failure> {
    load_with_request(robot).map(|(robot, _)| robot)
}

/// [`load`], with what the file asks of the simplified models (its `[simplify]`, a URDF's
/// `<limit>`s), as the derive reads them for `file = ".."` or `urdf = ".."`.
fn load_with_request(robot: &RobotFile) -> Result<(Robot, front::FileRequest), Failure> {
    let path = robot.path.as_str();
    let text = std::fs::read_to_string(path).map_err(|e| Failure::File(format!("{path}: {e}")))?;
    // `file:line:col: message`, or `file: message` when the error has no place.
    let at = |e: &front::FileError| {
        let sep = if e.line.is_some() && e.column.is_some() {
            ":"
        } else {
            ": "
        };
        format!("{path}{sep}{e}")
    };
    let mut limits = None;
    let loaded = if path.ends_with(".urdf") {
        let chain = front::Chain {
            base: robot.base.as_deref(),
            tip: robot.tip.as_deref(),
        };
        let loaded = front::load_urdf(path, &text, chain, true).map_err(|errors| {
            let lines: Vec<String> = errors.iter().map(at).collect();
            Failure::File(lines.join("\ndynamics: "))
        })?;
        limits = front::joint_limits(&text, chain).ok();
        loaded
    } else if robot.base.is_some() || robot.tip.is_some() {
        let message =
            format!("--base and --tip name links of a URDF file; `{path}` is not one (*.urdf)");
        return Err(Failure::Usage(
            Cli::command().error(ErrorKind::ArgumentConflict, message),
        ));
    } else {
        front::load(path, &text).map_err(|e| Failure::File(at(&e)))?
    };
    let mut loaded = loaded;
    if let Some(tool) = &robot.tool {
        loaded.robot.tool = Some(tool_placement(path, tool, loaded.robot.tool.is_some())?);
    }
    let problems: Vec<String> = check::robot(&loaded.robot, &loaded.check_inertia)
        .iter()
        .map(|problem| loaded.describe(path, problem))
        .collect();
    if problems.is_empty() {
        let request = front::FileRequest {
            given: loaded.simplify,
            limits,
            path: path.to_owned(),
        };
        Ok((loaded.robot, request))
    } else {
        Err(Failure::File(problems.join("\ndynamics: ")))
    }
}

/// The simplified models of `robot` that the file's `request` asks for, each key of
/// `overrides` (the command line's) in place of the file's; `None` where neither asks. A
/// mistake of the file's is a file error, one of the command line's a usage error of
/// `command`.
fn simplification(
    robot: &Robot,
    request: &front::FileRequest,
    overrides: &[(&'static str, Vec<f64>)],
    command: &str,
) -> Result<Option<Simplification>, Failure> {
    request.resolve(robot, overrides).map_err(|problems| {
        match problems.iter().find(|p| !p.in_file) {
            // The command line's options as the user wrote them, not the file's keys.
            Some(p) => {
                let mut message = p.message.clone();
                for key in front::SIMPLIFY_KEYS {
                    let option = format!("--{}", key.replace('_', "-"));
                    message = message.replace(&format!("`{key}`"), &option);
                }
                eval::usage(command, &message)
            }
            None => {
                let lines: Vec<String> = problems.into_iter().map(|p| p.message).collect();
                Failure::File(lines.join("\ndynamics: "))
            }
        }
    })
}

/// The simplified models of `request` built into `eq` (the family `Simplified`), as the
/// derive builds them; the error of one that cannot be (`path: simplify: ...`).
fn add_simplified(
    eq: &mut Equations,
    request: Option<&Simplification>,
    path: &str,
) -> Result<(), Failure> {
    match request {
        Some(request) => dynamics_codegen::simplify::add(eq, request)
            .map_err(|e| Failure::File(format!("{path}: simplify: {e}"))),
        None => Ok(()),
    }
}

/// `--tool x,y,z,roll,pitch,yaw` as the robot's tool, refused where the file has one: a URDF's
/// hand frame is its tip link (choose it with `--tip`), and a description's own `tool` would be
/// overridden unseen.
fn tool_placement(path: &str, tool: &Tool, declared: bool) -> Result<Placement, Failure> {
    let message = if path.ends_with(".urdf") {
        format!("--tool: the hand frame of `{path}` is its tip link; choose it with --tip")
    } else if declared {
        format!("--tool: `{path}` declares a `tool` already")
    } else {
        let [x, y, z, roll, pitch, yaw] = tool.0.map(Value::from_f64);
        return Ok(Placement {
            xyz: [x, y, z],
            rpy: [roll, pitch, yaw],
        });
    };
    Err(Failure::Usage(
        Cli::command().error(ErrorKind::ArgumentConflict, message),
    ))
}

/// `two_link` → `TwoLink`: the name of the struct the generated code implements `Dynamics` for.
fn type_name(name: &str) -> syn::Ident {
    let mut out = String::new();
    for part in name.split(|c: char| !c.is_ascii_alphanumeric()) {
        let mut chars = part.chars();
        if let Some(c) = chars.next() {
            out.push(c.to_ascii_uppercase());
            out.extend(chars);
        }
    }
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert_str(0, "Robot");
    }
    syn::Ident::new(&out, Span::call_site())
}

/// The struct's fields, one per parameter, as the generated code reads them: `self.m1`, ...
fn field_idents(eq: &Equations) -> Vec<syn::Ident> {
    eq.fields
        .iter()
        .map(|f| syn::Ident::new(f, Span::call_site()))
        .collect()
}

fn self_fields(idents: &[syn::Ident]) -> Vec<TokenStream> {
    idents.iter().map(|i| quote!(self.#i)).collect()
}
