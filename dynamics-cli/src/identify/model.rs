//! A model linear in its parameters, `τ_i = Σ_k Y_ik(q, q̇, q̈) π_k`, whose regressor entries are
//! nodes of a robot's expression graph, evaluated at each sample by a [`Tape`] of only the nodes
//! they need.
//!
//! Entries that are the constant zero are not evaluated: joint i's equation keeps the
//! parameters whose column is not identically zero in its row ([`LinearModel::columns`]).

use dynamics_codegen::symbolic::{Graph, NodeId, Tape, Var};

/// How a leaf of the regressor gets its value at a sample.
#[derive(Clone, Copy, Debug)]
enum Leaf {
    Q(usize),
    Sin(usize, f64),
    Cos(usize, f64),
    Qd(usize),
    Qdd(usize),
    Constant(f64),
}

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
    tape: Tape,
    leaves: Vec<Leaf>,
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
    leaves: Vec<f64>,
    tape: Vec<f64>,
}

impl LinearModel {
    /// The model of `entries`.
    ///
    /// # Errors
    /// An entry that depends on something a sample does not give (a wrench, a torque).
    pub fn new(entries: &Entries<'_>) -> Result<LinearModel, String> {
        let graph = entries.graph;
        let constants = |ids: &[NodeId]| constant_values(graph, ids, entries.fields);
        let offsets: Vec<f64> = {
            let ids: Vec<NodeId> = entries.angle_offsets.iter().flatten().copied().collect();
            let mut values = constants(&ids).into_iter();
            let offsets = entries.angle_offsets.iter();
            offsets
                .map(|o| o.and_then(|_| values.next()).unwrap_or(0.0))
                .collect()
        };
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
        let tape = Tape::new(graph, &outputs);
        let leaves = tape
            .leaves()
            .iter()
            .map(|&v| leaf(v, &offsets, entries.fields))
            .collect::<Result<_, _>>()?;
        Ok(LinearModel {
            names: entries.names.clone(),
            described: constants(&entries.described),
            columns,
            tape,
            leaves,
        })
    }

    /// The number of joints.
    #[must_use]
    pub fn joints(&self) -> usize {
        self.columns.len()
    }

    /// The regressor's entries at one state, joint after joint, each joint's in the order of
    /// its [`LinearModel::columns`]; `out` has room for all of them.
    pub fn rows(&self, q: &[f64], qd: &[f64], qdd: &[f64], work: &mut Work, out: &mut [f64]) {
        work.leaves.clear();
        work.leaves
            .extend(self.leaves.iter().map(|leaf| match *leaf {
                Leaf::Q(i) => q[i],
                Leaf::Sin(i, offset) => (q[i] + offset).sin(),
                Leaf::Cos(i, offset) => (q[i] + offset).cos(),
                Leaf::Qd(i) => qd[i],
                Leaf::Qdd(i) => qdd[i],
                Leaf::Constant(x) => x,
            }));
        self.tape.eval(&work.leaves, &mut work.tape, out);
    }

    /// The number of entries [`LinearModel::rows`] gives.
    #[must_use]
    pub fn entries(&self) -> usize {
        self.columns.iter().map(Vec::len).sum()
    }
}

/// How leaf `v` gets its value.
fn leaf(v: Var, offsets: &[f64], fields: &[f64]) -> Result<Leaf, String> {
    Ok(match v {
        Var::Q(i) => Leaf::Q(i.into()),
        Var::SinQ(i) => Leaf::Sin(i.into(), offsets[usize::from(i)]),
        Var::CosQ(i) => Leaf::Cos(i.into(), offsets[usize::from(i)]),
        Var::Qd(i) => Leaf::Qd(i.into()),
        Var::Qdd(i) => Leaf::Qdd(i.into()),
        Var::Param(k) => Leaf::Constant(fields[usize::from(k)]),
        Var::Wrench(_) | Var::Tau(_) | Var::Inertial(_) | Var::Exact(_) => {
            return Err(format!(
                "the regressor depends on {v:?}, which a measured sample does not give"
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
