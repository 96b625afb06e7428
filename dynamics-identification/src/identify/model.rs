//! A model linear in its parameters, `τ_i = Σ_k Y_ik(q, q̇, q̈) π_k`, whose regressor entries are
//! nodes of a robot's expression graph, evaluated four samples at a time by a [`JointTape`] of
//! only the nodes they need.
//!
//! Entries that are the constant zero are not evaluated: joint i's equation keeps the
//! parameters whose column is not identically zero in its row ([`LinearModel::columns`]).

use crate::joint_tape::{constant_values, gather, JointTape};
use crate::lanes::{Four, LANES};
use dynamics_codegen::pipeline::{Graph, NodeId, TapeScalar};

/// The regressor of a linear model, ready to evaluate.
#[derive(Clone, Debug)]
pub struct LinearModel {
    /// One per parameter.
    pub names: Vec<String>,
    /// The parameters' values in the description.
    pub described: Vec<f64>,
    /// Per joint: the parameters whose column is not identically zero in its equation, in the
    /// order [`LinearModel::rows`] gives their entries.
    pub columns: Vec<Vec<usize>>,
    tape: JointTape,
}

/// What a robot's graph gives a model: its entries `rows[i][k]` (joint i, parameter k; `None`
/// for an entry known to be zero), the parameters' names and values in the description, and
/// the robot's fields' values.
pub struct Entries<'a> {
    pub graph: &'a Graph,
    pub names: Vec<String>,
    pub rows: Vec<Vec<Option<NodeId>>>,
    pub described: Vec<NodeId>,
    pub angle_offsets: &'a [Option<NodeId>],
    pub fields: &'a [f64],
}

/// Scratch space for [`LinearModel::rows`].
#[derive(Default)]
pub struct Work {
    tape: crate::joint_tape::Work,
    entries: Vec<Four>,
}

/// One sample's state: positions, velocities and accelerations of every joint.
#[derive(Clone, Copy)]
pub struct JointValues<'a> {
    pub q: &'a [f64],
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
}

impl LinearModel {
    /// The model of `entries`.
    ///
    /// # Errors
    /// An entry that depends on something a sample does not give (a wrench, a torque).
    pub fn new(entries: &Entries<'_>) -> Result<LinearModel, String> {
        let graph = entries.graph;
        let nonzero = |entry: &Option<NodeId>| entry.filter(|&id| !graph.is_zero(id));
        let columns: Vec<Vec<usize>> = entries
            .rows
            .iter()
            .map(|row| {
                (0..row.len())
                    .filter(|&k| nonzero(&row[k]).is_some())
                    .collect()
            })
            .collect();
        let outputs: Vec<NodeId> = entries
            .rows
            .iter()
            .flat_map(|row| row.iter().filter_map(nonzero))
            .collect();
        let tape = JointTape::new(graph, &outputs, entries.angle_offsets, entries.fields, None)
            .map_err(|e| format!("the regressor: {e}"))?;
        Ok(LinearModel {
            names: entries.names.clone(),
            described: constant_values(graph, &entries.described, entries.fields),
            columns,
            tape,
        })
    }

    /// The number of joints.
    #[must_use]
    pub fn joints(&self) -> usize {
        self.columns.len()
    }

    /// The regressor's entries at up to [`LANES`] states, evaluated together (one state per
    /// lane): state `s`'s entries, joint after joint, each joint's in the order of its
    /// [`LinearModel::columns`], at `out[s * entries..(s + 1) * entries]`.
    ///
    /// # Panics
    /// With no state or more than [`LANES`], or `out` shorter than theirs.
    pub fn rows(&self, states: &[JointValues<'_>], work: &mut Work, out: &mut [f64]) {
        assert!((1..=LANES).contains(&states.len()), "1 to {LANES} states");
        let lanes = |values: Vec<&[f64]>| -> Vec<Four> {
            (0..self.joints()).map(|j| gather(&values, j)).collect()
        };
        let q = lanes(states.iter().map(|s| s.q).collect());
        let qd = lanes(states.iter().map(|s| s.qd).collect());
        let qdd = lanes(states.iter().map(|s| s.qdd).collect());
        let entries = self.entries();
        work.entries.resize(entries, Four::splat(0.0));
        self.tape
            .eval(&q, &qd, &qdd, &mut work.tape, &mut work.entries);
        for (e, value) in work.entries.iter().enumerate() {
            for (s, x) in value.lanes().into_iter().take(states.len()).enumerate() {
                out[s * entries + e] = x;
            }
        }
    }

    /// The number of entries [`LinearModel::rows`] gives.
    #[must_use]
    pub fn entries(&self) -> usize {
        self.columns.iter().map(Vec::len).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::{JointValues, LinearModel, Work, LANES};
    use crate::identify::base;
    use dynamics_codegen::JointColumns;
    use dynamics_codegen::Numeric;

    /// PUMA 560's base regressor in four lanes: each state's entries the same bits alone as in
    /// a group (a partial one too), and `Y_B π_B` the torques of the numeric Newton-Euler.
    #[test]
    fn four_states_at_once_as_one_at_a_time() {
        let text = include_str!("../../../robots/puma560.toml");
        let robot = dynamics_codegen::load(&dynamics_codegen::Source {
            path: "puma560.toml",
            text: Some(text),
            ..dynamics_codegen::Source::default()
        })
        .expect("reads")
        .robot;
        let mut eq = dynamics_codegen::derive(&robot);
        let base = eq
            .base_parameters(&robot, &[JointColumns::default(); 6])
            .expect("numbers only");
        let model = LinearModel::new(&base::entries(&eq, &base, &[])).expect("a model");
        let values: Vec<[Vec<f64>; 3]> = (0..5)
            .map(|k| {
                let x = |i: usize, scale: f64| (0.37 * (k * 6 + i) as f64).sin() * scale;
                [
                    (0..6).map(|i| x(i, 2.0)).collect(),
                    (0..6).map(|i| x(i + 40, 1.5)).collect(),
                    (0..6).map(|i| x(i + 80, 3.0)).collect(),
                ]
            })
            .collect();
        let states: Vec<JointValues> = values
            .iter()
            .map(|[q, qd, qdd]| JointValues { q, qd, qdd })
            .collect();
        let entries = model.entries();
        let mut work = Work::default();
        let mut together = vec![0.0; 2 * LANES * entries];
        model.rows(&states[..4], &mut work, &mut together);
        model.rows(&states[4..], &mut work, &mut together[4 * entries..]);
        let numeric = Numeric::new(&robot, &[]).expect("no fields");
        for (k, s) in states.iter().enumerate() {
            let mut alone = vec![0.0; LANES * entries];
            model.rows(&[*s], &mut work, &mut alone);
            let ours = &together[k * entries..(k + 1) * entries];
            assert_eq!(ours, &alone[..entries], "state {k}");
            let tau = numeric.inverse_dynamics(s.q, s.qd, s.qdd);
            let mut start = 0;
            for (i, columns) in model.columns.iter().enumerate() {
                let row = &ours[start..start + columns.len()];
                let y_pi: f64 = row
                    .iter()
                    .zip(columns)
                    .map(|(y, &c)| y * model.described[c])
                    .sum();
                assert!(
                    (y_pi - tau[i]).abs() < 1e-10 * (1.0 + tau[i].abs()),
                    "state {k}, joint {i}"
                );
                start += columns.len();
            }
        }
    }
}
