//! The base parameters: the combinations of the standard parameters that the joint torques
//! determine. `τ = Y(q, q̇, q̈) π` is linear in the standard parameters `π` (the links' ten, the
//! joints' actuator inertia and friction coefficients), but some columns of `Y` are zero
//! (a parameter with no effect on τ) and some are linear combinations of others,
//! `Y_c = Σ_b β_cb Y_b`. Then `Y π = Σ_b Y_b (π_b + Σ_c β_cb π_c)`: the reduced regressor `Y_B`
//! of the independent columns, of full column rank, and the base parameters
//! `π_B = π_b + Σ_c β_cb π_c` (Khalil and Gautier's grouping; `ZZR1 = ZZ1 + YY2 + …` in their
//! notation) give the same torques, and only `π_B` can be identified from them.
//!
//! The relations are decided exactly ([`exact`]), not from a numerical rank: the columns, as
//! the trace has them, evaluated in `ℤ/p` at random points. The columns are taken link by
//! link from the base, each link's `XX, XY, XZ, YZ, ZZ, MX, MY, YY, MZ, M`, then the joints'
//! `IA, FV, FC, FO` asked for; a column is a base column when it is independent of the columns
//! before it, so a parameter is grouped into the links nearer the base, `YY` into `XX` and
//! `ZZ`, and the mass and `MZ` of a link into its predecessors, as Khalil's rules group them.

mod coefficients;
mod exact;

use super::Equations;
use crate::model::{Joint, Robot, Value};
use crate::symbolic::{NodeId, Number};

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
        let regressor = self.regressor.clone()?;
        let n = self.dof;
        let zero = self.graph.num(Number::ZERO);
        let mut parameters = Vec::new();
        let mut columns: Vec<Vec<NodeId>> = Vec::new();
        let mut values = Vec::new();
        for link in 0..n {
            for index in LINK_ORDER {
                parameters.push(Parameter::Link { link, index });
                columns.push((0..n).map(|i| regressor.columns[i][link][index]).collect());
                values.push(regressor.parameters[link][index]);
            }
        }
        for (joint, asked) in joints.iter().enumerate().take(n) {
            for (index, _) in asked.included().iter().enumerate().filter(|(_, &a)| a) {
                parameters.push(Parameter::Joint { joint, index });
                let row = regressor.joint_columns[joint][index];
                columns.push(
                    (0..n)
                        .map(|i| if i == joint { row } else { zero })
                        .collect(),
                );
                values.push(regressor.joint_parameters[joint][index]);
            }
        }
        // Exactly on a trace of their own, in which the description's constants are leaves.
        let mut exact = super::regressor::exact_columns(robot);
        let exact_zero = exact.graph.num(Number::ZERO);
        let mut exact_columns: Vec<Vec<NodeId>> = Vec::new();
        for link in 0..n {
            for index in LINK_ORDER {
                exact_columns.push((0..n).map(|i| exact.columns[i][link][index]).collect());
            }
        }
        for (joint, asked) in joints.iter().enumerate().take(n) {
            for (index, _) in asked.included().iter().enumerate().filter(|(_, &a)| a) {
                let row = exact.joint_columns[joint][index];
                let column = (0..n).map(|i| if i == joint { row } else { exact_zero });
                exact_columns.push(column.collect());
            }
        }
        let relations = exact::relations(&exact.graph, &exact_columns, &exact.leaves)?;
        let pivots = relations.pivots;
        let numbers =
            coefficients::numbers(&self.graph, &columns, &pivots, &relations.coefficients);
        let mut groups: Vec<Vec<Term>> = pivots
            .iter()
            .map(|&c| {
                vec![Term {
                    parameter: parameters[c],
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
                no_effect.push(parameters[c]);
            }
            for (group, coefficient) in groups.iter_mut().zip(row) {
                if !coefficient.is_zero() {
                    group.push(Term {
                        parameter: parameters[c],
                        coefficient: *coefficient,
                    });
                }
            }
        }
        let base_values = groups
            .iter()
            .map(|terms| {
                let g = &mut self.graph;
                terms.iter().fold(zero, |sum, term| {
                    let c = g.num(term.coefficient);
                    let at = parameters.iter().position(|p| *p == term.parameter);
                    let value = at.map_or(zero, |k| values[k]);
                    let product = g.mul(c, value);
                    g.add(sum, product)
                })
            })
            .collect();
        Some(BaseParameters {
            parameters: groups
                .into_iter()
                .map(|terms| BaseParameter {
                    name: base_name(&terms),
                    terms,
                })
                .collect(),
            no_effect,
            standard: columns.len(),
            regressor: (0..n)
                .map(|i| pivots.iter().map(|&c| columns[c][i]).collect())
                .collect(),
            values: base_values,
        })
    }
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
