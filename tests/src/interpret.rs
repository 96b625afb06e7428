//! The expression graph of a robot without struct fields interpreted at one state: every node's
//! value, as the generated code would compute it, for the tests that check the trace itself on
//! random robots.

use dynamics_codegen::Equations;

/// The joint variables, and the torques the forward dynamics' graph reads.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    pub q: &'a [f64],
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
    pub tau: &'a [f64],
}

/// The value of every node of `eq.graph` at `state`, with a zero wrench: the front door's
/// evaluation ([`Equations::evaluate`]), by node index.
///
/// # Panics
/// If the graph reads a struct field: the robot must have none.
#[must_use]
pub fn evaluate(eq: &Equations, state: State) -> Vec<f64> {
    let State { q, qd, qdd, tau } = state;
    let state = dynamics_codegen::State {
        fields: &[],
        q,
        qd,
        qdd,
        tau,
    };
    eq.evaluate(&state).into_vec()
}
