//! Outputs of a robot's expression graph as functions of the joint values: a [`Tape`] of only
//! the nodes they need, whose leaves (q, sin and cos of the joint angles, q̇, q̈, the robot's
//! fields, given torques) are filled from four states at once and evaluated in [`Four`]
//! lanes. `identify` and `excite` evaluate the regressor so, `simulate --batch` the forward
//! dynamics.

use crate::lanes::Four;
use dynamics_codegen::pipeline::{Graph, NodeId, Tape, TapeScalar, Var};

/// How a leaf gets its value at a state.
#[derive(Clone, Copy, Debug)]
enum Leaf {
    Q(usize),
    Sin(usize, f64),
    Cos(usize, f64),
    Qd(usize),
    Qdd(usize),
    Constant(f64),
}

/// Some outputs of a graph, ready to evaluate at joint values.
#[derive(Clone, Debug)]
pub struct JointTape {
    tape: Tape,
    leaves: Vec<Leaf>,
}

/// Scratch space for [`JointTape::eval`].
#[derive(Default)]
pub struct Work {
    leaves: Vec<Four>,
    tape: Vec<Four>,
}

impl JointTape {
    /// The tape of `outputs` of `graph`, whose angles are offset by `angle_offsets` (nodes of
    /// the fields alone), with the fields' values `fields` and, where the outputs depend on
    /// joint torques, `tau`.
    ///
    /// # Errors
    /// An output that depends on something a state does not give (a wrench, a torque without
    /// `tau`).
    pub fn new(
        graph: &Graph,
        outputs: &[NodeId],
        angle_offsets: &[Option<NodeId>],
        fields: &[f64],
        tau: Option<&[f64]>,
    ) -> Result<JointTape, String> {
        let offsets: Vec<f64> = {
            let ids: Vec<NodeId> = angle_offsets.iter().flatten().copied().collect();
            let mut values = constant_values(graph, &ids, fields).into_iter();
            angle_offsets
                .iter()
                .map(|o| o.and_then(|_| values.next()).unwrap_or(0.0))
                .collect()
        };
        let tape = Tape::new(graph, outputs);
        let leaves = tape
            .leaves()
            .iter()
            .map(|&v| leaf(v, &offsets, fields, tau))
            .collect::<Result<_, _>>()?;
        Ok(JointTape { tape, leaves })
    }

    /// The outputs at the states in the lanes of `q`, `qd` and `qdd` (one state per lane).
    pub fn eval(&self, q: &[Four], qd: &[Four], qdd: &[Four], work: &mut Work, out: &mut [Four]) {
        work.leaves.clear();
        work.leaves
            .extend(self.leaves.iter().map(|leaf| match *leaf {
                Leaf::Q(i) => q[i],
                Leaf::Sin(i, offset) => (q[i] + Four::splat(offset)).sin(),
                Leaf::Cos(i, offset) => (q[i] + Four::splat(offset)).cos(),
                Leaf::Qd(i) => qd[i],
                Leaf::Qdd(i) => qdd[i],
                Leaf::Constant(x) => Four::splat(x),
            }));
        self.tape.eval_in(&work.leaves, &mut work.tape, out);
    }
}

/// Value `j` of `LANES` states side by side, the states past `states` repeating the last.
pub fn gather(states: &[&[f64]], j: usize) -> Four {
    Four::from_fn(|l| states[l.min(states.len() - 1)][j])
}

/// How leaf `v` gets its value.
fn leaf(v: Var, offsets: &[f64], fields: &[f64], tau: Option<&[f64]>) -> Result<Leaf, String> {
    Ok(match (v, tau) {
        (Var::Q(i), _) => Leaf::Q(i.into()),
        (Var::SinQ(i), _) => Leaf::Sin(i.into(), offsets[usize::from(i)]),
        (Var::CosQ(i), _) => Leaf::Cos(i.into(), offsets[usize::from(i)]),
        (Var::Qd(i), _) => Leaf::Qd(i.into()),
        (Var::Qdd(i), _) => Leaf::Qdd(i.into()),
        (Var::Param(k), _) => Leaf::Constant(fields[usize::from(k)]),
        (Var::Tau(i), Some(tau)) => Leaf::Constant(tau[usize::from(i)]),
        (
            Var::Wrench(_) | Var::TipWrench(_) | Var::Tau(_) | Var::Inertial(_) | Var::Exact(_),
            _,
        ) => {
            return Err(format!(
                "the equations depend on {v:?}, which a state does not give"
            ))
        }
    })
}

/// The values of nodes that depend on the robot's fields only.
pub fn constant_values(graph: &Graph, ids: &[NodeId], fields: &[f64]) -> Vec<f64> {
    let tape = Tape::new(graph, ids);
    let leaves: Vec<f64> = tape
        .leaves()
        .iter()
        .map(|v| match v {
            Var::Param(k) => fields[usize::from(*k)],
            // A value of the description depends on no joint variable.
            _ => f64::NAN,
        })
        .collect();
    let mut out = vec![0.0; ids.len()];
    tape.eval(&leaves, &mut Vec::new(), &mut out);
    out
}
