//! `dynamics eval ROBOT --q .. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]`: τ, M, C and
//! g at one state.

// `inspect.rs` imports `usage` from here (left to the helper moving `inspect`).
pub(crate) use super::usage;
use super::values::{joints, settings};
use super::{load, Failure};
use crate::args::Eval;
use crate::format::{self, Evaluation};
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::{derive, Equations};

pub fn run(args: &Eval) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = derive(&robot);
    let n = eq.dof;
    let q = joints("eval", "--q", Some(&args.q), n)?;
    let qd = joints("eval", "--qd", args.qd.as_ref(), n)?;
    let qdd = joints("eval", "--qdd", args.qdd.as_ref(), n)?;
    let params = settings("eval", &robot, &args.set)?;
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
