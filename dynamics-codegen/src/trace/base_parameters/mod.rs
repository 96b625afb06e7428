//! The base parameters: the combinations of the standard parameters that the joint torques
//! determine. `τ = Y(q, q̇, q̈) π` is linear in the standard parameters `π` (the links' ten, the
//! joints' actuator inertia and friction coefficients), but some columns of `Y` are zero
//! (a parameter with no effect on τ) and some are linear combinations of others,
//! `Y_c = Σ_b β_cb Y_b`. Then `Y π = Σ_b Y_b (π_b + Σ_c β_cb π_c)`: the reduced regressor `Y_B`
//! of the independent columns, of full column rank, and the base parameters
//! `π_B = π_b + Σ_c β_cb π_c` (Khalil and Gautier's grouping; `ZZR1 = ZZ1 + YY2 + …` in their
//! notation) give the same torques, and only `π_B` can be identified from them.
//!
//! The relations are decided exactly (`exact.rs`), not from a numerical rank: the columns, as
//! the trace has them, evaluated in `ℤ/p` at random points. The columns are taken link by
//! link from the base, each link's `XX, XY, XZ, YZ, ZZ, MX, MY, YY, MZ, M`, then the joints'
//! `IA, FV, FC, FO` asked for; a column is a base column when it is independent of the columns
//! before it, so a parameter is grouped into the links nearer the base, `YY` into `XX` and
//! `ZZ`, and the mass and `MZ` of a link into its predecessors, as Khalil's rules group them.

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod coefficients;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod exact;

use super::Equations;
use crate::model::{Joint, Robot, Value};
use crate::symbolic::{Graph, NodeId, Number};

/// The standard parameters of a link, in `π`'s order (`[m, m cx, m cy, m cz, Ixx, Ixy, Iyy,
/// Ixz, Iyz, Izz]`), in Khalil's notation.
pub const LINK_NAMES: [&str; 10] = ["M", "MX", "MY", "MZ", "XX", "XY", "YY", "XZ", "YZ", "ZZ"];

/// A joint's parameters, in `joint_regressor`'s order: actuator inertia, viscous, Coulomb and
/// offset friction.
pub const JOINT_NAMES: [&str; 4] = ["IA", "FV", "FC", "FO"];

/// The order in which a link's parameters are taken: the inertia before the first moments
/// before the mass, `YY` after `XX` and `ZZ`, so that those are the ones grouped into others.
const LINK_ORDER: [usize; 10] = [4, 5, 7, 8, 9, 1, 2, 6, 3, 0];

/// A standard parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Parameter {
    /// Parameter `index` of link `link` (0-based), in `π`'s order.
    Link { link: usize, index: usize },
    /// Parameter `index` of joint `joint` (0-based), in [`JOINT_NAMES`]' order.
    Joint { joint: usize, index: usize },
}

impl Parameter {
    /// Its name in Khalil's notation, 1-based: `ZZ1`, `M2`, `IA3`.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Parameter::Link { link, index } => format!("{}{}", LINK_NAMES[index], link + 1),
            Parameter::Joint { joint, index } => format!("{}{}", JOINT_NAMES[index], joint + 1),
        }
    }
}

/// Which of a joint's own parameters take part.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JointColumns {
    pub actuator_inertia: bool,
    pub viscous: bool,
    pub coulomb: bool,
    pub offset: bool,
}

impl JointColumns {
    /// The parameters a joint's description gives: its actuator inertia where it is not a
    /// literal zero, its friction coefficients where it has friction.
    #[must_use]
    pub fn described(joint: &Joint) -> JointColumns {
        let friction = joint.link.friction.is_some();
        JointColumns {
            actuator_inertia: joint.link.actuator_inertia != Value::Num(Number::ZERO),
            viscous: friction,
            coulomb: friction,
            offset: friction,
        }
    }

    fn included(self) -> [bool; 4] {
        [
            self.actuator_inertia,
            self.viscous,
            self.coulomb,
            self.offset,
        ]
    }
}

/// A standard parameter's part in a base parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Term {
    pub parameter: Parameter,
    pub coefficient: Number,
}

/// A base parameter: `Σ coefficient · parameter` over its terms, the first the base column's
/// own parameter with coefficient 1.
#[derive(Clone, Debug, PartialEq)]
pub struct BaseParameter {
    /// The first term's name, with `R` before the joint number where others are grouped into it
    /// (`ZZR1`).
    pub name: String,
    pub terms: Vec<Term>,
}

/// The base parameters of a robot.
#[derive(Clone, Debug)]
pub struct BaseParameters {
    pub parameters: Vec<BaseParameter>,
    /// The standard parameters with no effect on the torques (zero columns).
    pub no_effect: Vec<Parameter>,
    /// How many standard parameters were considered.
    pub standard: usize,
    /// `Y_B`: row i, column b, node ids into [`Equations::graph`].
    pub regressor: Vec<Vec<NodeId>>,
    /// `π_B` of the description, node ids.
    pub values: Vec<NodeId>,
    /// `P[b][j][k]`: base parameter b's coefficient on link j's standard parameter k, constant
    /// nodes.
    pub link_map: Blocks,
    /// `P_J[b][i][k]`: its coefficient on joint i's parameter k.
    pub joint_map: Blocks,
}

impl Equations {
    /// The base parameters of `robot` (whose equations these are), with the joint parameters
    /// `joints[i]` says for joint i; traces the regressor if it is not yet. `None` where the
    /// columns depend on a struct field (a length or angle given by a field), whose value the
    /// relations' coefficients would depend on.
    pub fn base_parameters(
        &mut self,
        robot: &Robot,
        joints: &[JointColumns],
    ) -> Option<BaseParameters> {
        if self.regressor.is_none() {
            self.add_regressor(robot);
        }
        // Exactly on a trace of their own, in which the description's constants are leaves.
        let exact = super::regressor::exact_columns(robot);
        self.grouped(joints, exact)
    }

    /// The base parameters of the regressor traced ([`Equations::regressor`]), the relations
    /// between its columns decided on `exact`, the same columns traced with the description's
    /// constants as leaves; with the joint parameters `joints[i]` says for joint i.
    pub(super) fn grouped(
        &mut self,
        joints: &[JointColumns],
        mut exact: super::regressor::ExactColumns,
    ) -> Option<BaseParameters> {
        let regressor = self.regressor.clone()?;
        // A column per link and joint, a row per coordinate (fewer on a robot with mimics).
        let links = regressor.parameters.len();
        let taken = taken(links, joints);
        let zero = self.graph.num(Number::ZERO);
        let ours = Columns {
            links: &regressor.columns,
            joints: &regressor.joint_columns,
            rows: &regressor.rows,
        };
        let columns = column_ids(&taken, &ours, zero);
        let exact_zero = exact.graph.num(Number::ZERO);
        let theirs = Columns {
            links: &exact.columns,
            joints: &exact.joint_columns,
            rows: &exact.rows,
        };
        let exact_columns = column_ids(&taken, &theirs, exact_zero);
        let relations = exact::relations(&exact.graph, &exact_columns, &exact.leaves)?;
        let pivots = relations.pivots;
        let numbers =
            coefficients::numbers(&self.graph, &columns, &pivots, &relations.coefficients);
        let (groups, no_effect) = groups(&taken, &pivots, &numbers);
        let values = groups
            .iter()
            .map(|terms| {
                let g = &mut self.graph;
                terms.iter().fold(zero, |sum, term| {
                    let c = g.num(term.coefficient);
                    let value = match term.parameter {
                        Parameter::Link { link, index } => regressor.parameters[link][index],
                        Parameter::Joint { joint, index } => {
                            regressor.joint_parameters[joint][index]
                        }
                    };
                    let product = g.mul(c, value);
                    g.add(sum, product)
                })
            })
            .collect();
        let (link_map, joint_map) = maps(&mut self.graph, links, &groups);
        Some(BaseParameters {
            link_map,
            joint_map,
            parameters: groups
                .into_iter()
                .map(|terms| BaseParameter {
                    name: base_name(&terms),
                    terms,
                })
                .collect(),
            no_effect,
            standard: taken.len(),
            regressor: (0..self.dof)
                .map(|i| pivots.iter().map(|&c| columns[c][i]).collect())
                .collect(),
            values,
        })
    }
}

/// The standard parameters taken, in the order in which they are taken: link by link, then
/// the joints' asked for.
fn taken(n: usize, joints: &[JointColumns]) -> Vec<Parameter> {
    let links = (0..n).flat_map(|link| LINK_ORDER.map(|index| Parameter::Link { link, index }));
    let joints = joints
        .iter()
        .enumerate()
        .take(n)
        .flat_map(|(joint, asked)| {
            let included = asked.included();
            (0..JOINT_NAMES.len())
                .filter(move |&index| included[index])
                .map(move |index| Parameter::Joint { joint, index })
        });
    links.chain(joints).collect()
}

/// A regressor's columns, as [`super::regressor::RegressorEquations`] has them.
struct Columns<'a> {
    links: &'a [Vec<Vec<NodeId>>],
    joints: &'a [Vec<NodeId>],
    rows: &'a [usize],
}

/// Per parameter, its column: `links[i][link][index]`, or joint j's `joints[j][index]` in its
/// row `rows[j]` and `zero` in the others.
fn column_ids(taken: &[Parameter], columns: &Columns<'_>, zero: NodeId) -> Vec<Vec<NodeId>> {
    let n = columns.links.len();
    taken
        .iter()
        .map(|p| match *p {
            Parameter::Link { link, index } => {
                (0..n).map(|i| columns.links[i][link][index]).collect()
            }
            Parameter::Joint { joint, index } => (0..n)
                .map(|i| {
                    if i == columns.rows[joint] {
                        columns.joints[joint][index]
                    } else {
                        zero
                    }
                })
                .collect(),
        })
        .collect()
}

/// Per pivot, its base parameter's terms (its own parameter first), and the parameters of the
/// zero columns: `numbers[c][r]`, column c's coefficient on pivot r.
fn groups(
    taken: &[Parameter],
    pivots: &[usize],
    numbers: &[Vec<Number>],
) -> (Vec<Vec<Term>>, Vec<Parameter>) {
    let mut groups: Vec<Vec<Term>> = pivots
        .iter()
        .map(|&c| {
            vec![Term {
                parameter: taken[c],
                coefficient: Number::ONE,
            }]
        })
        .collect();
    let mut no_effect = Vec::new();
    for (c, row) in numbers.iter().enumerate() {
        if pivots.contains(&c) {
            continue;
        }
        if row.iter().all(|x| x.is_zero()) {
            no_effect.push(taken[c]);
        }
        for (group, coefficient) in groups.iter_mut().zip(row) {
            if !coefficient.is_zero() {
                group.push(Term {
                    parameter: taken[c],
                    coefficient: *coefficient,
                });
            }
        }
    }
    (groups, no_effect)
}

/// Matrices of nodes, one after the other.
type Blocks = Vec<Vec<Vec<NodeId>>>;

/// The groups as maps from the links' and the joints' parameters, constant nodes.
fn maps(graph: &mut Graph, n: usize, groups: &[Vec<Term>]) -> (Blocks, Blocks) {
    let zero = graph.num(Number::ZERO);
    let mut links = vec![vec![vec![zero; LINK_NAMES.len()]; n]; groups.len()];
    let mut joints = vec![vec![vec![zero; JOINT_NAMES.len()]; n]; groups.len()];
    for (b, terms) in groups.iter().enumerate() {
        for term in terms {
            let c = graph.num(term.coefficient);
            match term.parameter {
                Parameter::Link { link, index } => links[b][link][index] = c,
                Parameter::Joint { joint, index } => joints[b][joint][index] = c,
            }
        }
    }
    (links, joints)
}

/// `ZZ1`, or `ZZR1` where other parameters are grouped into it.
fn base_name(terms: &[Term]) -> String {
    let name = terms[0].parameter.name();
    if terms.len() == 1 {
        return name;
    }
    let digits = name
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(name.len());
    format!("{}R{}", &name[..digits], &name[digits..])
}
