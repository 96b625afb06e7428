//! `dynamics eval ROBOT --q .. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]`: τ, M, C and
//! g at one state.

// `inspect.rs` imports `usage` from here (left to the helper moving `inspect`).
pub(crate) use super::usage;
use super::values::{coordinates, settings};
use super::{load, Failure};
use crate::args::Eval;
use crate::format::{self, Evaluation};
use dynamics_codegen::{derive, State};

pub fn run(args: &Eval) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = derive(&robot);
    let q = coordinates("eval", "--q", Some(&args.q), &robot)?;
    let qd = coordinates("eval", "--qd", args.qd.as_ref(), &robot)?;
    let qdd = coordinates("eval", "--qdd", args.qdd.as_ref(), &robot)?;
    let params = settings("eval", &robot, &args.set)?;
    let values = eq.evaluate(&State {
        fields: &params,
        q: &q,
        qd: &qd,
        qdd: &qdd,
        tau: &[],
    });
    let e = Evaluation {
        tau: values.vector(&eq.tau),
        m: values.matrix(&eq.mass),
        c: values.matrix(&eq.coriolis),
        g: values.vector(&eq.gravity),
    };
    Ok(if args.json {
        format::json(&e)
    } else {
        format::text(&e)
    })
}
