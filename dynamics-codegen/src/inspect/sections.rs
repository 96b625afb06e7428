//! The printed equations in sections, one per quantity: each entry names the equation and
//! holds its arranged terms, or nothing when it did not fit the limits.

use super::arrange::{factored_terms, terms, Term};
use super::branches;
use super::label::{Label, Quantity};
use crate::model::Robot;
use crate::poly::Expander;
use crate::trace::Equations;

/// One printed equation: its names (`D12 = D21`) and its right-hand side, `None` when it was
/// too large to expand.
pub(super) struct Entry {
    pub(super) labels: Vec<Label>,
    pub(super) value: Option<Vec<Term>>,
}

/// The equations of one quantity.
pub(super) struct Section {
    pub(super) quantity: Quantity,
    pub(super) entries: Vec<Entry>,
}

/// Every section of `eq`, in the order printed; expanded cheapest first (gravity first), so
/// that what fits the limits is printed.
pub(super) fn sections(x: &mut Expander<'_>, eq: &Equations, robot: &Robot) -> Vec<Section> {
    let n = eq.dof;
    let entry = |x: &mut Expander<'_>, labels, id| Entry {
        labels,
        value: terms(x, id),
    };
    let gravity = (0..n)
        .map(|i| entry(x, vec![Label::new(Quantity::Gravity, &[i])], eq.gravity[i]))
        .collect();
    let inertia = inertia(x, eq, robot);
    let mut christoffel = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in j..n {
                let mut labels = vec![Label::new(Quantity::Christoffel, &[i, j, k])];
                if k != j {
                    labels.push(Label::new(Quantity::Christoffel, &[i, k, j]));
                }
                christoffel.push(entry(x, labels, eq.christoffel[i][j][k]));
            }
        }
    }
    let mut coriolis = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let labels = vec![Label::new(Quantity::Coriolis, &[i, j])];
            coriolis.push(entry(x, labels, eq.coriolis[i][j]));
        }
    }
    // Only for a robot with friction, whose T_i has it.
    let friction = (0..n)
        .filter(|_| eq.friction.iter().any(|&f| !eq.graph.is_zero(f)))
        .map(|i| {
            entry(
                x,
                vec![Label::new(Quantity::Friction, &[i])],
                eq.friction[i],
            )
        })
        .collect();
    let torque = (0..n)
        .map(|i| entry(x, vec![Label::new(Quantity::Torque, &[i])], eq.tau[i]))
        .collect();
    [
        (Quantity::Inertia, inertia),
        (Quantity::Christoffel, christoffel),
        (Quantity::Coriolis, coriolis),
        (Quantity::Gravity, gravity),
        (Quantity::Friction, friction),
        (Quantity::Torque, torque),
    ]
    .into_iter()
    .filter(|(quantity, entries): &(Quantity, Vec<Entry>)| {
        *quantity != Quantity::Friction || !entries.is_empty()
    })
    .map(|(quantity, entries)| Section { quantity, entries })
    .collect()
}

/// `D_ij = D_ji` for `j ≥ i`, the diagonal named with the actuator inertia where the joint
/// has one (M's diagonal holds it).
fn inertia(x: &mut Expander<'_>, eq: &Equations, robot: &Robot) -> Vec<Entry> {
    let mut entries = Vec::new();
    let antecedents = branches::antecedents(robot);
    for (i, joint) in robot.joints.iter().enumerate() {
        for j in i..eq.dof {
            if !branches::related(antecedents.as_deref(), i, j) {
                continue;
            }
            let mut labels = vec![Label::new(Quantity::Inertia, &[i, j])];
            if j != i {
                labels.push(Label::new(Quantity::Inertia, &[j, i]));
            } else if !joint.link.actuator_inertia.is_zero() {
                labels[0] = labels[0].clone().with_actuator_inertia();
            }
            entries.push(Entry {
                labels,
                value: terms(x, eq.mass[i][j]),
            });
        }
    }
    entries
}

/// The hand pose `[n o a p]` column by column (`nx`, `ny`, `nz`, `ox`, …), and the hand's
/// Jacobian in the base frame and in the hand frame (ᴴJ), row by row.
pub(super) fn kinematic_sections(x: &mut Expander<'_>, eq: &Equations) -> Vec<Section> {
    let k = &eq.kinematics;
    let pose = (0..4)
        .flat_map(|column| (0..3).map(move |row| (row, column)))
        .map(|(row, column)| Entry {
            labels: vec![Label::new(Quantity::HandPose, &[row, column])],
            value: factored_terms(x, k.hand_pose[row][column]),
        })
        .collect();
    let mut jacobian = |quantity, rows: &[Vec<_>]| {
        let mut entries = Vec::new();
        for (i, row) in rows.iter().enumerate() {
            for (j, &id) in row.iter().enumerate() {
                entries.push(Entry {
                    labels: vec![Label::new(quantity, &[i, j])],
                    value: factored_terms(x, id),
                });
            }
        }
        Section { quantity, entries }
    };
    let in_base = jacobian(Quantity::JacobianInBase, &k.jacobian_in_base);
    let in_hand = jacobian(Quantity::JacobianInHand, &k.jacobian_in_hand);
    vec![
        Section {
            quantity: Quantity::HandPose,
            entries: pose,
        },
        in_base,
        in_hand,
    ]
}
