//! The equations at one state, in plain `f64`: every node of the graph evaluated as the
//! generated code evaluates its closed forms, for the commands that print numbers (`dynamics
//! eval`) and the tests that check the graph against the code derived from it.

use crate::symbolic::{NodeId, Var};
use crate::trace::Equations;

/// A state of the robot, and the values of its parameters.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    /// The robot's parameters, in the order of its fields (`Robot::fields`).
    pub fields: &'a [f64],
    /// Joint positions.
    pub q: &'a [f64],
    /// Joint velocities.
    pub qd: &'a [f64],
    /// Joint accelerations.
    pub qdd: &'a [f64],
    /// Joint torques, which the forward dynamics read; empty for none applied.
    pub tau: &'a [f64],
}

/// Every node of the equations' graph at one [`State`].
#[derive(Clone, Debug)]
pub struct Values(Vec<f64>);

impl Values {
    /// The value of node `id`.
    #[must_use]
    pub fn of(&self, id: NodeId) -> f64 {
        self.0[id.index()]
    }

    /// The values of `ids`.
    #[must_use]
    pub fn vector(&self, ids: &[NodeId]) -> Vec<f64> {
        ids.iter().map(|&id| self.of(id)).collect()
    }

    /// Every node's value, by node index.
    #[must_use]
    pub fn into_vec(self) -> Vec<f64> {
        self.0
    }

    /// The values of `rows`, rows first.
    #[must_use]
    pub fn matrix(&self, rows: &[Vec<NodeId>]) -> Vec<Vec<f64>> {
        rows.iter().map(|row| self.vector(row)).collect()
    }
}

impl Equations {
    /// Every node at `state`. No wrench is given: the statics are those of a zero wrench; the
    /// forward dynamics are the motion under `state.tau` (none applied where it is empty).
    ///
    /// # Panics
    /// If `state` has fewer joints or fields than the equations read.
    #[must_use]
    pub fn evaluate(&self, state: &State<'_>) -> Values {
        let State {
            fields,
            q,
            qd,
            qdd,
            tau,
        } = *state;
        // A robot with mimic joints keeps its joints' leaves past its coordinates in the graph,
        // read by no output: zero.
        let at = |x: &[f64], i: u16| x.get(usize::from(i)).copied().unwrap_or(0.0);
        let leaf = |v: Var, offsets: &[f64]| -> f64 {
            match v {
                Var::Q(i) => at(q, i),
                Var::SinQ(i) => (at(q, i) + at(offsets, i)).sin(),
                Var::CosQ(i) => (at(q, i) + at(offsets, i)).cos(),
                Var::Qd(i) => at(qd, i),
                Var::Qdd(i) => at(qdd, i),
                Var::Param(k) => fields[usize::from(k)],
                Var::Tau(i) => tau.get(usize::from(i)).copied().unwrap_or(0.0),
                Var::Wrench(_) | Var::TipWrench(_) => 0.0,
                // The regressor's placeholders: the equations' outputs never read them.
                Var::Inertial(_) | Var::Exact(_) => 0.0,
            }
        };
        // The angle offsets depend on the parameters only: a first pass finds them.
        let zeros = vec![0.0; self.dof];
        let first = self.graph.eval(|v| leaf(v, &zeros));
        let offsets: Vec<f64> = self
            .angle_offsets
            .iter()
            .map(|o| o.map_or(0.0, |id| first[id.index()]))
            .collect();
        Values(self.graph.eval(|v| leaf(v, &offsets)))
    }
}
