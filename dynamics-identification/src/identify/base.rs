//! The model `dynamics identify` estimates: the robot's base parameters `π_B`, with the
//! reduced regressor `Y_B` of full column rank, so that `τ = Y_B π_B` (the combinations of the
//! standard parameters that the torques determine, as `dynamics inspect --base-parameters`
//! prints them), for the links and the joint terms asked for.

use super::model::Entries;
use crate::joint_tape::constant_values;
use dynamics_codegen::Equations;
use dynamics_codegen::{BaseParameters, JointColumns, Parameter};

/// The standard parameters behind the base parameters, for the consistent estimate: the links'
/// ten each, then the joint terms taken, joint by joint in `IA, FV, FC, FO` order.
pub struct Standard {
    pub parameters: Vec<Parameter>,
    /// The description's values.
    pub described: Vec<f64>,
    /// `map[b][k]`: base parameter b's coefficient on standard parameter k.
    pub map: Vec<Vec<f64>>,
}

/// The standard parameters of `base`, with joint i's terms `columns[i]`. `eq` has its regressor
/// (`base_parameters` traced it).
#[must_use]
pub fn standard(
    eq: &Equations,
    base: &BaseParameters,
    columns: &[JointColumns],
    fields: &[f64],
) -> Standard {
    let Some(regressor) = eq.regressor.as_ref() else {
        unreachable!("base parameters are found from the traced regressor")
    };
    let n = regressor.parameters.len();
    let mut parameters: Vec<Parameter> = (0..n)
        .flat_map(|link| (0..10).map(move |index| Parameter::Link { link, index }))
        .collect();
    for (joint, c) in columns.iter().enumerate().take(n) {
        let flags = [c.actuator_inertia, c.viscous, c.coulomb, c.offset];
        parameters.extend(
            (0..4)
                .filter(|&k| flags[k])
                .map(|index| Parameter::Joint { joint, index }),
        );
    }
    let ids: Vec<_> = parameters
        .iter()
        .map(|p| match *p {
            Parameter::Link { link, index } => regressor.parameters[link][index],
            Parameter::Joint { joint, index } => regressor.joint_parameters[joint][index],
        })
        .collect();
    let described = constant_values(&eq.graph, &ids, fields);
    let map = base
        .parameters
        .iter()
        .map(|b| {
            let mut row = vec![0.0; parameters.len()];
            for term in &b.terms {
                if let Some(k) = parameters.iter().position(|p| *p == term.parameter) {
                    row[k] += term.coefficient.to_f64();
                }
            }
            row
        })
        .collect();
    Standard {
        parameters,
        described,
        map,
    }
}

/// The entries of the base parameters' model `base` of `eq`.
#[must_use]
pub fn entries<'a>(eq: &'a Equations, base: &BaseParameters, fields: &'a [f64]) -> Entries<'a> {
    Entries {
        graph: &eq.graph,
        names: base.parameters.iter().map(|p| p.name.clone()).collect(),
        rows: base
            .regressor
            .iter()
            .map(|row| row.iter().copied().map(Some).collect())
            .collect(),
        described: base.values.clone(),
        angle_offsets: &eq.angle_offsets,
        fields,
    }
}

/// The joint terms taken, in words: `actuator inertia (joints 1, 2), viscous (joints 1-4)`, or
/// `none`.
#[must_use]
pub fn describe(columns: &[JointColumns]) -> String {
    let names = ["actuator inertia", "viscous", "Coulomb", "offset"];
    let flags = |c: &JointColumns| [c.actuator_inertia, c.viscous, c.coulomb, c.offset];
    let parts: Vec<String> = names
        .iter()
        .enumerate()
        .filter_map(|(k, name)| {
            let joints: Vec<usize> = (1..=columns.len())
                .filter(|&j| flags(&columns[j - 1])[k])
                .collect();
            (!joints.is_empty()).then(|| format!("{name} ({})", joint_list(&joints, columns.len())))
        })
        .collect();
    if parts.is_empty() {
        "none".into()
    } else {
        parts.join(", ")
    }
}

/// `every joint`, or `joints 1, 3`.
fn joint_list(joints: &[usize], n: usize) -> String {
    if joints.len() == n && n > 1 {
        return "every joint".into();
    }
    let numbers: Vec<String> = joints.iter().map(usize::to_string).collect();
    let word = if joints.len() == 1 { "joint" } else { "joints" };
    format!("{word} {}", numbers.join(", "))
}
