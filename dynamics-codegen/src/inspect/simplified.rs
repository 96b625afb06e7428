//! Simplified joint torques, mass matrix, Coriolis torques and gravity torques printed with
//! their proven bounds (`dynamics inspect --simplified`): the simplify stage's pruning, with no
//! cap, arranged as the equations of motion are (the bound and how it is proven:
//! `crate::simplify`).

use super::arrange::arrange;
use super::label::{Label, Quantity};
use super::sections::{Entry, Section};
use super::{Inspection, Limits};
use crate::method::Method;
use crate::model::{Envelope, Robot, Simplification};
use crate::simplify::{prune_outputs, Caps, Pruned, Pruning};
use crate::trace::Equations;

/// The pruned outputs of a robot, ready to print.
pub struct Simplified {
    pub(super) inspection: Inspection,
    pub(super) envelope: Envelope,
    /// Each element's name (`T1`, `D12`) and pruning, in the order printed.
    pub(super) elements: Vec<(String, Pruning)>,
}

/// The printed outputs, in the method table's order, with the quantity each prints as.
const PRINTED: [(Method, Quantity); 4] = [
    (Method::InverseDynamicsSimplified, Quantity::Torque),
    (Method::MassMatrixSimplified, Quantity::Inertia),
    (Method::CoriolisTorquesSimplified, Quantity::CoriolisTorque),
    (Method::GravityTorquesSimplified, Quantity::Gravity),
];

/// Expands each joint torque, mass matrix element, Coriolis torque and gravity torque of `eq`,
/// folds it and prunes it within `request` (see `crate::simplify` for the bound).
///
/// # Errors
/// An envelope or tolerance list whose length is not the joints', or a robot with a parameter
/// (a struct field) in its outputs or angle offsets.
pub fn inspect_simplified(
    eq: &Equations,
    robot: &Robot,
    request: &Simplification,
) -> Result<Simplified, String> {
    let mut outputs = prune_outputs(eq, request, Caps::NONE)?;
    let mut sections = Vec::new();
    let mut elements = Vec::new();
    for (method, quantity) in PRINTED {
        let Some(at) = outputs.iter().position(|o| o.output.method == method) else {
            continue;
        };
        let output = outputs.swap_remove(at);
        let pruned = output
            .elements
            .map_err(|f| format!("{}: {f}", method.name()))?;
        let mut entries = Vec::new();
        for Pruned {
            row,
            column,
            pruning,
        } in pruned
        {
            let (indices, name) = match column {
                None => (vec![row], format!("{}{}", output.output.letter, row + 1)),
                Some(j) => (
                    vec![row, j],
                    format!("{}{}{}", output.output.letter, row + 1, j + 1),
                ),
            };
            entries.push(Entry {
                labels: vec![Label::new(quantity, &indices)],
                value: Some(arrange(pruning.kept.clone().into_iter().collect())),
            });
            elements.push((name, pruning));
        }
        sections.push(Section { quantity, entries });
    }
    Ok(Simplified {
        inspection: Inspection::new(eq, robot, false, sections, Limits::UNBOUNDED),
        envelope: request.envelope.clone(),
        elements,
    })
}
