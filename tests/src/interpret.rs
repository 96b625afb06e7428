//! The expression graph of a robot without struct fields interpreted at one state: every node's
//! value, as the generated code would compute it, for the tests that check the trace itself on
//! random robots.

use dynamics_codegen::symbolic::Var;
use dynamics_codegen::Equations;

/// The joint variables, and the torques the forward dynamics' graph reads.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    pub q: &'a [f64],
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
    pub tau: &'a [f64],
}

/// The value of every node of `eq.graph` at `state`, with a zero wrench.
///
/// # Panics
/// If the graph reads a struct field: the robot must have none.
#[must_use]
pub fn evaluate(eq: &Equations, state: State) -> Vec<f64> {
    // The offsets are constant nodes: their values do not depend on the inputs.
    let constants = eq.graph.eval(|_| 0.0);
    let offset = |i: u16| eq.angle_offsets[usize::from(i)].map_or(0.0, |id| constants[id.index()]);
    let State { q, qd, qdd, tau } = state;
    eq.graph.eval(|v| match v {
        Var::Q(i) => q[usize::from(i)],
        Var::SinQ(i) => (q[usize::from(i)] + offset(i)).sin(),
        Var::CosQ(i) => (q[usize::from(i)] + offset(i)).cos(),
        Var::Qd(i) => qd[usize::from(i)],
        Var::Qdd(i) => qdd[usize::from(i)],
        Var::Tau(i) => tau[usize::from(i)],
        Var::Param(k) => panic!("the robot has no struct fields, yet parameter {k} appears"),
        // The regressor's placeholders never reach its outputs.
        Var::Wrench(_) | Var::Inertial(_) | Var::Exact(_) => 0.0,
    })
}
