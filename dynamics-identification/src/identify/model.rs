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
    /// The count of q̇ (and q̈) values of a state, and where the tape's q starts in a state's
    /// q: the rows' count and 0 on a fixed base; `n + 6` and 1 on a floating one, whose graph
    /// reads `Var::Q(k)` as `q[k + 1]` (`y, z, qx, qy, qz, qw`, then the joints).
    variables: usize,
    q_offset: usize,
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
            variables: columns.len(),
            columns,
            tape,
            q_offset: 0,
        })
    }

    /// The model of a floating base's graph, whose states have `velocities` values of q̇ and
    /// q̈ and one more of q, the graph's `Var::Q(k)` being `q[k + 1]`.
    #[must_use]
    pub fn on_floating_base(mut self, velocities: usize) -> LinearModel {
        self.variables = velocities;
        self.q_offset = 1;
        self
    }

    /// The number of joints: of rows of τ (a floating base's six among them, unless the
    /// joints' rows alone are fitted).
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
            (0..self.variables).map(|j| gather(&values, j)).collect()
        };
        let q = lanes(states.iter().map(|s| &s.q[self.q_offset..]).collect());
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
