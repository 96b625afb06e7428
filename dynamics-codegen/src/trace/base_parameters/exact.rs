//! Which columns of the regressor are linear combinations of the columns before them, and with
//! which coefficients, decided exactly: the columns evaluated in `ℤ/p` ([`crate::symbolic::modular`])
//! at random points, each point's n rows added to a row-echelon basis until a point adds no
//! rank, then reduced to the reduced row-echelon form `R`. Row operations keep the relations
//! between columns, so column c is `Σ_r R[r][c] · column(lead_r)` of the pivot columns, the leads
//! of `R`'s rows: each of them independent of the columns before it.

use crate::symbolic::modular::{self, Fp, Points};
use crate::symbolic::{Graph, Node, NodeId, Var};
use std::collections::HashMap;

/// The relations found.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Relations {
    /// The pivot columns, ascending.
    pub pivots: Vec<usize>,
    /// Per column, its coefficients on `pivots` (a pivot: 1 on itself).
    pub coefficients: Vec<Vec<Fp>>,
}

/// The relations between `columns[c][i]` (column c, row i), in the columns' order, or `None`
/// where the columns depend on a leaf that is not a joint variable (a struct field).
/// The leaf [`Var::Exact`]`(k)` is `leaves[k]`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn relations(graph: &Graph, columns: &[Vec<NodeId>], leaves: &[Fp]) -> Option<Relations> {
    let outputs: Vec<NodeId> = columns.iter().flatten().copied().collect();
    let mask = modular::needed(graph, &outputs);
    let only_joint_variables = graph.nodes().all(|(id, node)| {
        !mask[id.index()]
            || !matches!(
                node,
                Node::Var(
                    Var::Param(_)
                        | Var::Wrench(_)
                        | Var::TipWrench(_)
                        | Var::Tau(_)
                        | Var::Inertial(_)
                )
            )
    });
    if !only_joint_variables {
        return None;
    }
    let width = columns.len();
    let rows = columns.first().map_or(0, Vec::len);
    let mut basis = Echelon::new(width);
    let mut points = Points::new(0x5eed_ba5e);
    let (mut unchanged, mut failures) = (0, 0);
    // A random point adds rank unless the rows so far already have it, save for a chance of
    // about 10⁻¹⁷: two points in a row that add none leave a wide margin.
    while unchanged < 2 && basis.rank() < width {
        let Some(values) = sample(graph, &mask, leaves, &mut points) else {
            // A reciprocal's operand vanished at this point: rare, unless it always does.
            failures += 1;
            if failures > 8 {
                return None;
            }
            continue;
        };
        let before = basis.rank();
        for i in 0..rows {
            basis.insert(columns.iter().map(|c| values[c[i].index()]).collect());
        }
        unchanged = if basis.rank() == before {
            unchanged + 1
        } else {
            0
        };
    }
    Some(basis.relations())
}

/// The graph at one random point: each revolute joint's sine and cosine on the unit circle,
/// the other joint variables random; a sign or tanh (friction's) a random value of its own.
fn sample(graph: &Graph, mask: &[bool], constants: &[Fp], points: &mut Points) -> Option<Vec<Fp>> {
    let mut leaves: HashMap<Var, Fp> = HashMap::new();
    let mut circles: HashMap<u16, (Fp, Fp)> = HashMap::new();
    let mut opaque: HashMap<Node, Fp> = HashMap::new();
    let mut angles: HashMap<NodeId, (Fp, Fp)> = HashMap::new();
    let mut for_leaves = Points::new(points.bits());
    let mut for_opaque = Points::new(points.bits());
    modular::eval(
        graph,
        mask,
        |v| match v {
            Var::SinQ(i) => circles.entry(i).or_insert_with(|| for_leaves.circle()).0,
            Var::CosQ(i) => circles.entry(i).or_insert_with(|| for_leaves.circle()).1,
            Var::Exact(k) => constants[usize::from(k)],
            _ => *leaves.entry(v).or_insert_with(|| for_leaves.residue()),
        },
        |node, operand| match node {
            Node::Sin(_) => {
                angles
                    .entry(operand)
                    .or_insert_with(|| for_opaque.circle())
                    .0
            }
            Node::Cos(_) => {
                angles
                    .entry(operand)
                    .or_insert_with(|| for_opaque.circle())
                    .1
            }
            _ => *opaque.entry(node).or_insert_with(|| for_opaque.residue()),
        },
    )
}

/// A row-echelon basis of the rows seen: each row's first nonzero entry (its lead) is 1, and
/// the leads are distinct.
struct Echelon {
    width: usize,
    /// Rows, by ascending lead.
    rows: Vec<(usize, Vec<Fp>)>,
}

impl Echelon {
    fn new(width: usize) -> Echelon {
        Echelon {
            width,
            rows: Vec::new(),
        }
    }

    fn rank(&self) -> usize {
        self.rows.len()
    }

    /// Adds `row` if it is not in the span of the rows so far.
    fn insert(&mut self, mut row: Vec<Fp>) {
        // Ascending leads: subtracting a row clears its lead and touches only later columns,
        // whose own rows come after.
        for (lead, basis) in &self.rows {
            let factor = row[*lead];
            if !factor.is_zero() {
                subtract(&mut row, basis, factor);
            }
        }
        let Some(lead) = row.iter().position(|x| !x.is_zero()) else {
            return;
        };
        let Some(scale) = row[lead].recip() else {
            return;
        };
        for x in &mut row {
            *x = *x * scale;
        }
        let at = self.rows.partition_point(|(l, _)| *l < lead);
        self.rows.insert(at, (lead, row));
    }

    /// Reduced to the reduced row-echelon form: each lead column zero in every other row.
    fn relations(mut self) -> Relations {
        for k in (0..self.rows.len()).rev() {
            let (lead, pivot_row) = self.rows[k].clone();
            for (_, row) in &mut self.rows[..k] {
                let factor = row[lead];
                if !factor.is_zero() {
                    subtract(row, &pivot_row, factor);
                }
            }
        }
        let pivots: Vec<usize> = self.rows.iter().map(|(lead, _)| *lead).collect();
        let coefficients = (0..self.width)
            .map(|c| self.rows.iter().map(|(_, row)| row[c]).collect())
            .collect();
        Relations {
            pivots,
            coefficients,
        }
    }
}

/// `row −= factor · other`.
fn subtract(row: &mut [Fp], other: &[Fp], factor: Fp) {
    for (x, y) in row.iter_mut().zip(other) {
        if !y.is_zero() {
            *x = *x - factor * *y;
        }
    }
}
