//! `dynamics`: the generator on the command line, for a robot description file (JSON or TOML,
//! as `#[dynamics(file = "...")]` reads).
//!
//! * `inspect ROBOT [--latex]`: the equations of motion in the book's notation;
//! * `emit ROBOT`: a standalone Rust module with the code the derive generates;
//! * `stats ROBOT`: expansion time, operation counts, longest chain of operations and code
//!   size per method, and the cost of the readable equations the derive adds;
//! * `eval ROBOT --q .. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]`: τ, M, C and g.
//!
//! Errors in the file are reported as `file:line:col: message` (exit code 1); usage errors
//! exit with code 2.

use dynamics_codegen::check;
use dynamics_codegen::front;
use dynamics_codegen::inspect::{self, Format, Limits};
use dynamics_codegen::model::Robot;
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::{derive, generate, Equations};
use quote::quote;
use std::fmt::Write;
use std::process::ExitCode;
use std::time::Instant;

const USAGE: &str = "usage:
  dynamics inspect ROBOT [--latex]      the equations of motion (Niku ch. 6 notation)
  dynamics emit ROBOT > robot.rs        a standalone Rust module with the generated code
  dynamics stats ROBOT                  expansion time, operation counts, depth and code size
  dynamics eval ROBOT --q Q1,Q2,.. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]
                                        tau, M, C and g at one state (qd, qdd default to 0)
ROBOT is a description file (.json or .toml).";

/// A failure: the message and the exit code.
struct Failure(String, u8);

fn usage(message: &str) -> Failure {
    Failure(format!("{message}\n{USAGE}"), 2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            print!("{out}");
            ExitCode::SUCCESS
        }
        Err(Failure(message, code)) => {
            eprintln!("dynamics: {message}");
            ExitCode::from(code)
        }
    }
}

fn run(args: &[String]) -> Result<String, Failure> {
    let Some(command) = args.first() else {
        return Err(usage("no command"));
    };
    if matches!(command.as_str(), "-h" | "--help" | "help") {
        return Ok(format!("{USAGE}\n"));
    }
    let Some(path) = args.get(1).filter(|a| !a.starts_with("--")) else {
        return Err(usage(&format!("`{command}` needs a ROBOT file")));
    };
    let options = &args[2..];
    match command.as_str() {
        "inspect" => {
            let latex = flags(options, &["--latex"])?.contains(&"--latex");
            let robot = load(path)?;
            let eq = derive(&robot);
            let format = if latex { Format::Latex } else { Format::Text };
            Ok(inspect::inspect(&eq, &robot, Limits::UNBOUNDED).render(format))
        }
        "emit" => {
            flags(options, &[])?;
            Ok(emit(path, &load(path)?))
        }
        "stats" => {
            flags(options, &[])?;
            Ok(stats(&load(path)?))
        }
        "eval" => eval(path, options),
        _ => Err(usage(&format!("unknown command `{command}`"))),
    }
}

/// Checks that `options` are among `allowed` flags (without values).
fn flags<'a>(options: &'a [String], allowed: &[&str]) -> Result<Vec<&'a str>, Failure> {
    options
        .iter()
        .map(|o| {
            if allowed.contains(&o.as_str()) {
                Ok(o.as_str())
            } else {
                Err(usage(&format!("unexpected argument `{o}`")))
            }
        })
        .collect()
}

/// Reads and checks a description file as the derive does (values, then the physical checks
/// of each link and the joint count); errors carry `file:line:col`.
fn load(path: &str) -> Result<Robot, Failure> {
    let text = std::fs::read_to_string(path).map_err(|e| Failure(format!("{path}: {e}"), 1))?;
    let loaded = front::load(path, &text).map_err(|e| Failure(format!("{path}:{e}"), 1))?;
    let problems: Vec<String> = check::robot(&loaded.robot, &loaded.check_inertia)
        .iter()
        .map(|problem| loaded.describe(path, problem))
        .collect();
    if problems.is_empty() {
        Ok(loaded.robot)
    } else {
        Err(Failure(problems.join("\ndynamics: "), 1))
    }
}

/// `two_link` → `TwoLink`.
fn type_name(name: &str) -> String {
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
    out
}

/// A standalone module: the robot's struct (one `f64` field per parameter) and its
/// `Dynamics` impl, exactly the methods the derive generates, formatted.
fn emit(path: &str, robot: &Robot) -> String {
    let eq = derive(robot);
    let krate = quote!(::dynamics_runtime);
    let idents: Vec<syn::Ident> = eq
        .fields
        .iter()
        .map(|f| syn::Ident::new(f, proc_macro2::Span::call_site()))
        .collect();
    let fields = idents.iter().map(|i| quote!(self.#i)).collect();
    let n = eq.dof;
    let generated = generate(&eq, fields);
    let ty = syn::Ident::new(&type_name(&robot.name), proc_macro2::Span::call_site());
    let items = generated.items(&krate, &ty, &syn::Generics::default(), &|method| {
        Some(format!(" {}", method.summary()))
    });
    let struct_doc = format!(" {}: {n} joints, read from `{path}`.", robot.name);
    let def = if idents.is_empty() {
        quote!(pub struct #ty;)
    } else {
        let docs = eq.fields.iter().map(|f| format!(" Parameter `{f}`."));
        quote!(pub struct #ty { #(#[doc = #docs] pub #idents: f64,)* })
    };
    let tokens = quote! {
        #[doc = #struct_doc]
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        #def
        #items
    };
    let body = match syn::parse2::<syn::File>(tokens.clone()) {
        Ok(file) => prettyplease::unparse(&file),
        // Not expected: the tokens are what the derive emits. Unformatted is still valid Rust.
        Err(_) => tokens.to_string(),
    };
    format!(
        "//! Generated by `dynamics emit {path}`; do not edit: change the description file\n\
         //! and run it again.\n//!\n//! The closed-form equations of motion of `{}` ({n} joints), as\n\
         //! `#[derive(Dynamics)]` would generate them. Depends on the `dynamics-runtime` crate.\n\n\
         {body}",
        robot.name
    )
}

#[allow(clippy::too_many_lines)] // until the clap rewrite splits the commands (issue 15)
fn stats(robot: &Robot) -> String {
    let start = Instant::now();
    let eq = derive(robot);
    let krate = quote!(::dynamics_runtime);
    let fields = eq
        .fields
        .iter()
        .map(|f| {
            let ident = proc_macro2::Ident::new(f, proc_macro2::Span::call_site());
            quote!(self.#ident)
        })
        .collect();
    let generated = generate(&eq, fields);
    let elapsed = start.elapsed();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}: {} joints, graph {} nodes, derived and emitted in {:.1} ms",
        robot.name,
        eq.dof,
        eq.graph.len(),
        elapsed.as_secs_f64() * 1e3
    );
    let _ = writeln!(
        out,
        "{:<18} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>6} {:>9}",
        "method", "mul", "add", "neg", "div", "trig", "flops", "depth", "bytes"
    );
    let mut total = 0;
    for (name, shared) in [
        ("(configuration)", &generated.configuration),
        ("(motion)", &generated.motion),
    ] {
        if let Some(c) = shared {
            let bytes = c.tokens.to_string().len();
            total += bytes;
            let _ = writeln!(
                out,
                "{:<18} {:>49} {:>9}",
                name, "computed once, counted below", bytes
            );
        }
    }
    for m in &generated.methods {
        let bytes = m.body.to_string().len();
        total += bytes;
        let o = m.ops;
        let _ = writeln!(
            out,
            "{:<18} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>6} {:>9}",
            m.name,
            o.mul,
            o.add,
            o.neg,
            o.div,
            o.trig,
            o.flops(),
            o.depth,
            bytes
        );
    }
    let _ = writeln!(out, "total generated code: {total} bytes");
    // With the signatures, the struct and the forwarding impl around them.
    let ty = syn::Ident::new(&type_name(&robot.name), proc_macro2::Span::call_site());
    let items = generated.items(&krate, &ty, &syn::Generics::default(), &|_| None);
    let _ = writeln!(
        out,
        "all items the derive emits: {} bytes",
        items.to_string().len()
    );
    // What the derive adds for `EQUATIONS` and `EQUATIONS_LATEX`, within its limits.
    let start = Instant::now();
    let inspection = inspect::inspect(&eq, robot, Limits::DERIVE);
    let (text, latex) = (
        inspection.render(Format::Text),
        inspection.render(Format::Latex),
    );
    let elapsed = start.elapsed();
    let _ = writeln!(
        out,
        "readable equations in the derive: {:.1} ms, {} + {} bytes (text + LaTeX), {}",
        elapsed.as_secs_f64() * 1e3,
        text.len(),
        latex.len(),
        if inspection.complete() {
            "complete"
        } else {
            "capped: some sections point to `dynamics inspect`"
        }
    );
    out
}

/// Parses `1,2.5,-3` into exactly `n` numbers.
fn vector(option: &str, text: &str, n: usize) -> Result<Vec<f64>, Failure> {
    let v: Vec<f64> = text
        .split(',')
        .map(|s| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| usage(&format!("{option}: `{s}` is not a finite number")))
        })
        .collect::<Result<_, _>>()?;
    if v.len() != n {
        return Err(usage(&format!(
            "{option}: {} values given, the robot has {n} joints",
            v.len()
        )));
    }
    Ok(v)
}

#[allow(clippy::too_many_lines)] // until the clap rewrite splits the commands (issue 15)
fn eval(path: &str, options: &[String]) -> Result<String, Failure> {
    let mut texts: [Option<&str>; 3] = [None; 3];
    let mut sets: Vec<(String, f64)> = Vec::new();
    let mut json = false;
    let mut it = options.iter();
    while let Some(o) = it.next() {
        let slot = match o.as_str() {
            "--json" => {
                json = true;
                continue;
            }
            "--q" => 0,
            "--qd" => 1,
            "--qdd" => 2,
            "--set" => 3,
            _ => return Err(usage(&format!("unexpected argument `{o}`"))),
        };
        let value = it
            .next()
            .ok_or_else(|| usage(&format!("`{o}` needs a value")))?;
        if slot == 3 {
            let (name, v) = value
                .split_once('=')
                .and_then(|(n, v)| Some((n.to_string(), v.parse::<f64>().ok()?)))
                .ok_or_else(|| usage(&format!("--set: `{value}` is not NAME=NUMBER")))?;
            sets.push((name, v));
        } else {
            texts[slot] = Some(value);
        }
    }
    let robot = load(path)?;
    let eq = derive(&robot);
    let n = eq.dof;
    let q = vector("--q", texts[0].ok_or_else(|| usage("eval needs --q"))?, n)?;
    let zero = vec![0.0; n];
    let qd = texts[1].map_or(Ok(zero.clone()), |t| vector("--qd", t, n))?;
    let qdd = texts[2].map_or(Ok(zero), |t| vector("--qdd", t, n))?;
    let mut params = Vec::with_capacity(eq.fields.len());
    for f in &eq.fields {
        let v = sets
            .iter()
            .find(|(name, _)| name == f)
            .map(|(_, v)| *v)
            .ok_or_else(|| {
                usage(&format!(
                    "the robot has a parameter `{f}`: give --set {f}=VALUE"
                ))
            })?;
        params.push(v);
    }
    if let Some((name, _)) = sets.iter().find(|(s, _)| !eq.fields.contains(s)) {
        return Err(usage(&format!(
            "--set: the robot has no parameter `{name}`"
        )));
    }
    let values = evaluate(&eq, &params, &q, &qd, &qdd);
    let vec_of = |ids: &[NodeId]| -> Vec<f64> { ids.iter().map(|id| values[id.index()]).collect() };
    let mat_of =
        |rows: &[Vec<NodeId>]| -> Vec<Vec<f64>> { rows.iter().map(|r| vec_of(r)).collect() };
    let (tau, m, c, g) = (
        vec_of(&eq.tau),
        mat_of(&eq.mass),
        mat_of(&eq.coriolis),
        vec_of(&eq.gravity),
    );
    if json {
        let doc = serde_json::json!({ "tau": tau, "M": m, "C": c, "g": g });
        return Ok(format!("{doc:#}\n"));
    }
    let row = |v: &[f64]| {
        let s: Vec<String> = v.iter().map(|x| format!("{x:>13.6e}")).collect();
        format!("[{}]", s.join(" "))
    };
    let mut out = String::new();
    let _ = writeln!(out, "tau = {}", row(&tau));
    for (name, mat) in [("M", &m), ("C", &c)] {
        let _ = writeln!(out, "{name} =");
        for r in mat {
            let _ = writeln!(out, "  {}", row(r));
        }
    }
    let _ = writeln!(out, "g   = {}", row(&g));
    Ok(out)
}

/// Every node of the equations' graph at one state: the same closed forms the generated code
/// evaluates.
fn evaluate(eq: &Equations, params: &[f64], q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    let base = |v: Var, offsets: &[f64]| -> f64 {
        match v {
            Var::Q(i) => q[usize::from(i)],
            Var::SinQ(i) => (q[usize::from(i)] + offsets[usize::from(i)]).sin(),
            Var::CosQ(i) => (q[usize::from(i)] + offsets[usize::from(i)]).cos(),
            Var::Qd(i) => qd[usize::from(i)],
            Var::Qdd(i) => qdd[usize::from(i)],
            Var::Param(k) => params[usize::from(k)],
        }
    };
    // The angle offsets depend on parameters only: a first pass finds them.
    let zeros = vec![0.0; eq.dof];
    let first = eq.graph.eval(|v| base(v, &zeros));
    let offsets: Vec<f64> = eq
        .angle_offsets
        .iter()
        .map(|o| o.map_or(0.0, |id| first[id.index()]))
        .collect();
    eq.graph.eval(|v| base(v, &offsets))
}
