//! `dynamics eval ROBOT --q .. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]`: τ, M, C and
//! g at one state.

use super::{load, Failure};
use crate::args::{Cli, Eval, Numbers, Setting};
use crate::format::{self, Evaluation};
use clap::error::ErrorKind;
use clap::CommandFactory;
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::{derive, Equations};

pub fn run(args: &Eval) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = derive(&robot);
    let n = eq.dof;
    let q = joints("eval", "--q", Some(&args.q), n)?;
    let qd = joints("eval", "--qd", args.qd.as_ref(), n)?;
    let qdd = joints("eval", "--qdd", args.qdd.as_ref(), n)?;
    let params = parameters("eval", &eq.fields, &args.set)?;
    let values = evaluate(&eq, &params, &q, &qd, &qdd);
    let vector = |ids: &[NodeId]| -> Vec<f64> { ids.iter().map(|id| values[id.index()]).collect() };
    let matrix =
        |rows: &[Vec<NodeId>]| -> Vec<Vec<f64>> { rows.iter().map(|r| vector(r)).collect() };
    let e = Evaluation {
        tau: vector(&eq.tau),
        m: matrix(&eq.mass),
        c: matrix(&eq.coriolis),
        g: vector(&eq.gravity),
    };
    Ok(if args.json {
        format::json(&e)
    } else {
        format::text(&e)
    })
}

/// A usage error of `command` found once the robot is known, reported as clap reports its own.
pub(super) fn usage(command: &str, message: &str) -> Failure {
    let mut cli = Cli::command();
    cli.build();
    let error = match cli.find_subcommand_mut(command) {
        Some(eval) => eval.error(ErrorKind::ValueValidation, message),
        None => cli.error(ErrorKind::ValueValidation, message),
    };
    Failure::Usage(error)
}

/// One value per joint, zeros when the option is not given.
pub(super) fn joints(
    command: &str,
    option: &str,
    given: Option<&Numbers>,
    n: usize,
) -> Result<Vec<f64>, Failure> {
    match given {
        None => Ok(vec![0.0; n]),
        Some(Numbers(v)) if v.len() == n => Ok(v.clone()),
        Some(Numbers(v)) => Err(usage(
            command,
            &format!(
                "{option}: {} values given, the robot has {n} joints",
                v.len()
            ),
        )),
    }
}

/// The value of each of the robot's parameters, in the order of its fields: each set exactly
/// once, none unknown.
pub(super) fn parameters(
    command: &str,
    fields: &[String],
    sets: &[Setting],
) -> Result<Vec<f64>, Failure> {
    if let Some(s) = sets.iter().find(|s| !fields.contains(&s.name)) {
        return Err(usage(
            command,
            &format!("--set: the robot has no parameter `{}`", s.name),
        ));
    }
    fields
        .iter()
        .map(
            |f| match sets.iter().filter(|s| &s.name == f).collect::<Vec<_>>()[..] {
                [s] => Ok(s.value),
                [] => Err(usage(
                    command,
                    &format!("the robot has a parameter `{f}`: give --set {f}=VALUE"),
                )),
                _ => Err(usage(
                    command,
                    &format!("--set: `{f}` given more than once"),
                )),
            },
        )
        .collect()
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
            // No wrench is given: the statics print the torques of a zero wrench.
            Var::Wrench(_) => 0.0,
            // Nor torques: the forward dynamics print the motion with no torque applied.
            Var::Tau(_) => 0.0,
            // The regressor's placeholders are never in the equations it evaluates.
            Var::Inertial(_) | Var::Exact(_) => 0.0,
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
