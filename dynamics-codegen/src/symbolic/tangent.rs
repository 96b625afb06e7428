//! Forward differentiation in lanes: the tangents of a graph's nodes by all n joint variables
//! at once, one direction per lane, planned at compile time and computed at run time.
//!
//! [`Graph::derivative_by`] builds each column of a Jacobian as scalar nodes, one column per
//! joint: `∂(a b)/∂x_j = b ∂a/∂x_j + a ∂b/∂x_j` n times. The n directions of a node undergo the
//! same operations on different numbers, so [`Graph::tangents`] plans them as one vector per
//! node instead, `∂v = (∂v/∂x_1, …, ∂v/∂x_n)`: a sum's tangent is the sum of its operands',
//! a product's `b ∂a + a ∂b` (a scalar broadcast times a vector, fused into the sum), so the
//! code is about n times shorter than the columns written apart. A tangent is kept as a sum
//! of terms, each a vector defined before times a product of at most two scalar nodes, or a
//! single lane (`∂ sin q_j = cos q_j e_j`: the leaves' tangents have one direction), and
//! written as a vector ([`Lane`]) only where several nodes read it, where a product would
//! multiply a sum of more than two terms, or at an output. Where a tangent would need a new
//! scalar node (a sine of a sum, a reciprocal, a hyperbolic tangent that depends on the
//! variables), there is no plan, and the caller differentiates column by column.
//!
//! The directions are held in blocks of [`Tangents::group`] lanes (a register each: [`BLOCK`],
//! or four where that costs less, [`Tangents::prefer_groups_of_four`]), and a lane only in the
//! blocks its terms reach ([`Tangents::blocks`]): on a tree a value depends on the joints of its
//! branch alone, so a finger's tangents take one block of the hand's, not all of them.

use super::calculus::Wrt;
use super::graph::Graph;
use super::node::{Node, NodeId, Var};
use core::ops::Range;

/// The directions a register holds: a lane is kept in whole blocks of this many (an AVX-512
/// register of `f64`), unless its plan takes [`QUARTER_BLOCK`].
pub const BLOCK: usize = 8;
/// The directions of a smaller block, an AVX register of `f64`.
pub const QUARTER_BLOCK: usize = 4;
/// The lane operations in blocks of [`BLOCK`] beyond which a plan keeps them: its function's
/// code outgrows the instruction cache, and fetching it costs more than the halves of 512-bit
/// operations that blocks of four would save.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub const FETCH_BOUND_OPERATIONS: usize = 1_000;

/// How many scalar factors a term may carry before its vector is written out.
const FACTORS: usize = 2;
/// How many terms a tangent may have where a product scales it.
const SCALED_TERMS: usize = 2;

/// A term of a tangent: `± f₁ f₂ ⋯ · x`, where `x` is a [`Lane`] (by index) or the unit
/// vector of one direction.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Term {
    /// The vector: a lane defined before, or the unit vector `e_j`.
    pub of: Of,
    /// Scalar factors (none: 1).
    pub factors: Vec<NodeId>,
    /// Whether the term is subtracted.
    pub negative: bool,
}

/// The vector a [`Term`] scales.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Of {
    /// [`Tangents::lanes`]`[k]`.
    Lane(usize),
    /// The unit vector of direction j (from 0).
    Unit(u16),
}

/// A vector of tangents written out: the sum of its terms, computed once the scalar node
/// `after` (the node it is the tangent of) and the lanes it reads are.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lane {
    /// The node whose tangent this is.
    pub after: NodeId,
    /// The terms.
    pub terms: Vec<Term>,
}

/// The plan: lanes in the order they are computed, and each output's lane.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Tangents {
    /// The number of directions (joints).
    pub directions: usize,
    /// The vectors written out, each reading only those before it.
    pub lanes: Vec<Lane>,
    /// Per output, its tangent's lane, or `None` where it is zero.
    pub outputs: Vec<Option<usize>>,
    /// The directions of a block: [`BLOCK`] or [`QUARTER_BLOCK`].
    pub group: usize,
}

impl Tangents {
    /// Every scalar node the lanes read as a factor.
    #[must_use]
    pub fn factors(&self) -> Vec<NodeId> {
        let mut all: Vec<NodeId> = self
            .lanes
            .iter()
            .flat_map(|l| l.terms.iter().flat_map(|t| t.factors.iter().copied()))
            .collect();
        all.sort_unstable();
        all.dedup();
        all
    }

    /// The blocks of [`Tangents::group`] directions of the whole tangent (`n` rounded up).
    #[must_use]
    pub fn block_count(&self) -> usize {
        self.directions.div_ceil(self.group).max(1)
    }

    /// The lane operations (a term that reads a lane, a lane's unit vectors together), each
    /// counted once per block of `group` directions it takes.
    #[must_use]
    pub fn block_operations(&self, group: usize) -> usize {
        let blocks = Tangents {
            group,
            ..self.clone()
        }
        .blocks();
        self.lanes
            .iter()
            .zip(blocks)
            .map(|(lane, blocks)| {
                let vectors = lane.terms.iter().filter(|t| matches!(t.of, Of::Lane(_)));
                let units = lane.terms.iter().any(|t| matches!(t.of, Of::Unit(_)));
                (vectors.count() + usize::from(units)) * blocks.len()
            })
            .sum()
    }

    /// Whether blocks of four cost less than of eight, where the CPU executes a 512-bit
    /// operation as two 256-bit halves (AMD's Zen 4): a lane within four directions takes one
    /// half, not two, and a lane of 5-8 two halves either way. Not where the plan's operations
    /// in blocks of eight pass `FETCH_BOUND_OPERATIONS` (1,000): there the count of instructions
    /// (each a few bytes of code to fetch) weighs more than their halves.
    #[must_use]
    pub fn prefer_groups_of_four(&self) -> bool {
        let eights = self.block_operations(BLOCK);
        eights <= FETCH_BOUND_OPERATIONS
            && self.block_operations(QUARTER_BLOCK) < eights * (BLOCK / QUARTER_BLOCK)
    }

    /// Per lane, the blocks it is kept in: the smallest run of blocks that holds every
    /// direction its terms can be nonzero in (outside it the lane is exactly zero). A lane's
    /// blocks hold those of every lane it reads, so a term is added block by block.
    #[must_use]
    pub fn blocks(&self) -> Vec<Range<usize>> {
        let mut blocks: Vec<Range<usize>> = Vec::with_capacity(self.lanes.len());
        for lane in &self.lanes {
            let hull = lane
                .terms
                .iter()
                .map(|t| match t.of {
                    Of::Lane(k) => blocks[k].clone(),
                    Of::Unit(j) => {
                        let b = usize::from(j) / self.group;
                        b..b + 1
                    }
                })
                .reduce(|a, b| a.start.min(b.start)..a.end.max(b.end));
            blocks.push(hull.unwrap_or(0..1));
        }
        blocks
    }
}

impl Graph {
    /// The plan of the tangents of `outputs` by the joint variables of kind `wrt` (positions
    /// or velocities) of `directions` joints, from the index in `wrt` on (the variables before
    /// it held fixed: a floating base's quaternion, whose tangent is not its components'), or
    /// `None` where one would need a scalar node the graph lacks.
    #[must_use]
    pub fn tangents(&self, outputs: &[NodeId], wrt: Wrt, directions: usize) -> Option<Tangents> {
        self.tangents_with(outputs, wrt, directions, FACTORS)
    }

    /// [`Graph::tangents`] with at most `factors` scalar factors to a term.
    #[must_use]
    pub fn tangents_with(
        &self,
        outputs: &[NodeId],
        wrt: Wrt,
        directions: usize,
        factors: usize,
    ) -> Option<Tangents> {
        let end = outputs.iter().map(|o| o.index() + 1).max().unwrap_or(0);
        let live = self.live(outputs);
        let mut readers = vec![0u32; end];
        for i in (0..end).filter(|&i| live[i]) {
            for a in self.nodes[i].operands() {
                readers[a.index()] += 1;
            }
        }
        for o in outputs {
            readers[o.index()] += 1;
        }
        let mut plan = Planner {
            lanes: Vec::new(),
            terms: vec![Vec::new(); end],
            factors,
        };
        for i in (0..end).filter(|&i| live[i]) {
            let id = NodeId(u32::try_from(i).expect("graph exceeds u32 nodes"));
            let terms = self.tangent_of(id, wrt, &mut plan)?;
            // Read by several nodes: written once, unless it is a lane or a unit already.
            let shared = readers[i] > 1 && !is_plain(&terms);
            plan.terms[i] = if shared { plan.write(id, terms) } else { terms };
        }
        let outputs = outputs
            .iter()
            .map(|&o| {
                let terms = plan.terms[o.index()].clone();
                match terms.as_slice() {
                    [] => None,
                    [Term {
                        of: Of::Lane(k),
                        factors,
                        negative: false,
                    }] if factors.is_empty() => Some(*k),
                    _ => match plan.write(o, terms).as_slice() {
                        [Term {
                            of: Of::Lane(k), ..
                        }] => Some(*k),
                        _ => unreachable!("a tangent written is one lane"),
                    },
                }
            })
            .collect();
        Some(Tangents {
            directions,
            lanes: plan.lanes,
            outputs,
            group: BLOCK,
        })
    }

    /// The tangent of node `id` as terms, from its operands' (already planned).
    fn tangent_of(&self, id: NodeId, wrt: Wrt, plan: &mut Planner) -> Option<Vec<Term>> {
        let unit = |j: u16, factors: Vec<NodeId>, negative: bool| {
            vec![Term {
                of: Of::Unit(j),
                factors,
                negative,
            }]
        };
        let zero = |plan: &Planner, a: NodeId| plan.terms[a.index()].is_empty();
        Some(match self.node(id) {
            Node::Const(_) => Vec::new(),
            Node::Var(v) => match (v, wrt) {
                (Var::Q(j), Wrt::Position(first)) | (Var::Qd(j), Wrt::Velocity(first))
                    if j >= first =>
                {
                    unit(j, Vec::new(), false)
                }
                (Var::SinQ(j), Wrt::Position(first)) if j >= first => {
                    unit(j, vec![self.find_var(Var::CosQ(j))?], false)
                }
                (Var::CosQ(j), Wrt::Position(first)) if j >= first => {
                    unit(j, vec![self.find_var(Var::SinQ(j))?], true)
                }
                _ => Vec::new(),
            },
            Node::Add(a, b) => {
                let mut t = plan.terms[a.index()].clone();
                t.extend(plan.terms[b.index()].iter().cloned());
                t
            }
            Node::Neg(a) => plan.terms[a.index()]
                .iter()
                .map(|t| Term {
                    negative: !t.negative,
                    ..t.clone()
                })
                .collect(),
            Node::Mul(a, b) => {
                let mut t = plan.scaled(a, b);
                t.extend(plan.scaled(b, a));
                t
            }
            // Flat away from 0, where friction's sign is not differentiated.
            Node::Sign(_) => Vec::new(),
            Node::Recip(a) | Node::Sin(a) | Node::Cos(a) | Node::Tanh(a) if zero(plan, a) => {
                Vec::new()
            }
            Node::Recip(_) | Node::Sin(_) | Node::Cos(_) | Node::Tanh(_) => return None,
        })
    }

    /// The node of leaf `v`, if the graph has it.
    fn find_var(&self, v: Var) -> Option<NodeId> {
        self.lookup(Node::Var(v))
    }
}

/// Whether a tangent is read as it is, with no vector arithmetic: zero, one lane at most
/// negated, or one direction (a unit vector times scalars, which a reader multiplies as
/// scalars).
fn is_plain(terms: &[Term]) -> bool {
    match terms {
        [] => true,
        [t] => t.factors.is_empty() || matches!(t.of, Of::Unit(_)),
        _ => false,
    }
}

/// The lanes written so far and each node's tangent as terms.
struct Planner {
    lanes: Vec<Lane>,
    terms: Vec<Vec<Term>>,
    /// How many scalar factors a term may carry ([`FACTORS`] unless asked otherwise).
    factors: usize,
}

impl Planner {
    /// Writes `terms` out as a lane, the tangent of `after`; returns the lane as a term.
    fn write(&mut self, after: NodeId, terms: Vec<Term>) -> Vec<Term> {
        self.lanes.push(Lane { after, terms });
        vec![Term {
            of: Of::Lane(self.lanes.len() - 1),
            factors: Vec::new(),
            negative: false,
        }]
    }

    /// `s · ∂a` as terms: each of `∂a`'s terms takes the factor `s`, unless `∂a` has too many
    /// terms or a term too many factors, when `∂a` is written out first.
    fn scaled(&mut self, a: NodeId, s: NodeId) -> Vec<Term> {
        let terms = &self.terms[a.index()];
        if terms.is_empty() {
            return Vec::new();
        }
        let crowded =
            terms.len() > SCALED_TERMS || terms.iter().any(|t| t.factors.len() >= self.factors);
        let terms = if crowded {
            let terms = terms.clone();
            let written = self.write(a, terms);
            self.terms[a.index()].clone_from(&written);
            written
        } else {
            terms.clone()
        };
        terms
            .into_iter()
            .map(|mut t| {
                t.factors.push(s);
                t
            })
            .collect()
    }
}
