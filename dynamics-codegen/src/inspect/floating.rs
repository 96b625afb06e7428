//! A floating base's readable equations (`dynamics inspect --floating`): `M`, `h`, `g` and `τ`
//! in Pinocchio's coordinates, named as `docs/floating-base.md` names them. The configuration
//! is `q = [x, y, z, qx, qy, qz, qw, θ1 … θn]`, the velocity `v = [vx, vy, vz, ωx, ωy, ωz,
//! θ1' … θn']` (the base origin's velocity and the base's angular velocity, in base axes), the
//! acceleration `a = v'`; rows and columns are named by the coordinate of `v` they belong to
//! (`M[vx, θ1]`, `τ[ωz]`). Gravity enters through `g_b = Rᵀ g` alone, its three components
//! (`gbx`, `gby`, `gbz`) printed first from the quaternion, then read by the other equations
//! ([`crate::trace::derive_floating_readable`]).

use super::arrange::terms;
use super::branches;
use super::label::{Label, Quantity};
use super::print::{Printer, BASE, GRAVITY};
use super::sections::{Entry, Section};
use super::{Inspection, Limits};
use crate::model::Robot;
use crate::poly::Expander;
use crate::symbolic::NodeId;
use crate::trace::{FloatingReadable, BASE_COORDINATES};
use std::fmt::Write;

/// The equations of `readable`, the floating-base robot `robot`'s, expanded and arranged within
/// `limits`: `g_b`, `M` (the upper triangle, without the zeros between two legs), `h`, `g`, `τ`.
#[must_use]
pub fn inspect_floating(readable: &FloatingReadable, robot: &Robot, limits: Limits) -> Inspection {
    let eq = &readable.eq;
    let x = &mut Expander::new(eq, limits);
    // The antecedents are the joints': with mimic joints the rows are the coordinates', whose
    // zeros between branches are not told (every entry is printed).
    let antecedents = branches::antecedents(robot).filter(|_| !robot.has_mimics());
    let vector = |x: &mut Expander<'_>, quantity, ids: &[NodeId]| Section {
        quantity,
        entries: (ids.iter().enumerate())
            .map(|(i, &id)| Entry {
                labels: vec![Label::new(quantity, &[i])],
                value: terms(x, id),
            })
            .collect(),
    };
    // Cheapest first, as `sections` expands, so that what fits the limits is printed.
    let base_gravity = vector(x, Quantity::BaseGravity, &readable.base_gravity);
    let gravity = vector(x, Quantity::FloatingGravity, &eq.gravity);
    let mut mass = Vec::new();
    for i in 0..eq.dof {
        for j in i..eq.dof {
            let joints = (
                i.checked_sub(BASE_COORDINATES),
                j.checked_sub(BASE_COORDINATES),
            );
            if let (Some(a), Some(b)) = joints {
                if !branches::related(antecedents.as_deref(), a, b) {
                    continue;
                }
            }
            let mut labels = vec![Label::new(Quantity::FloatingMass, &[i, j])];
            if i != j {
                labels.push(Label::new(Quantity::FloatingMass, &[j, i]));
            }
            mass.push(Entry {
                labels,
                value: terms(x, eq.mass[i][j]),
            });
        }
    }
    let mass = Section {
        quantity: Quantity::FloatingMass,
        entries: mass,
    };
    let bias = vector(x, Quantity::FloatingBias, &eq.bias);
    let tau = vector(x, Quantity::FloatingTorque, &eq.tau);
    Inspection {
        name: robot.name.clone(),
        kinematics: false,
        floating: true,
        kinds: eq.kinds[BASE_COORDINATES..].to_vec(),
        offsets: eq.angle_offsets.iter().any(Option::is_some),
        mimics: robot.has_mimics(),
        antecedents,
        sections: vec![base_gravity, mass, bias, gravity, tau],
        limits,
    }
}

impl Printer<'_> {
    /// Coordinate `i` of `v`: `vx` … `ωz`, then `θ1`, `d2` (a prismatic joint).
    fn coordinate(&self, i: usize) -> String {
        match i.checked_sub(BASE_COORDINATES) {
            None => self.pick(BASE[i]),
            Some(j) => format!("{}{}", self.joint_letter(j), self.indices(&[j])),
        }
    }

    /// The name of a floating base's equation (`M[vx, θ1]`, `τ[ωz]`, `gbx`; in LaTeX
    /// `M_{v_x \theta_{1}}`); `None` for the fixed base's quantities.
    pub(super) fn floating_label(&self, quantity: Quantity, at: &[usize]) -> Option<String> {
        let (text, latex) = match quantity {
            Quantity::BaseGravity => return Some(self.pick(GRAVITY[at[0]])),
            Quantity::FloatingMass => ("M", "M"),
            Quantity::FloatingBias => ("h", "h"),
            Quantity::FloatingGravity => ("g", "g"),
            Quantity::FloatingTorque => ("τ", "\\tau"),
            _ => return None,
        };
        let names: Vec<String> = at.iter().map(|&i| self.coordinate(i)).collect();
        Some(if self.latex() {
            format!("{latex}_{{{}}}", names.join(" "))
        } else {
            format!("{text}[{}]", names.join(", "))
        })
    }
}

impl Inspection {
    /// The robot's name, its coordinates, Pinocchio's conventions and the notation.
    pub(super) fn floating_header(&self, p: &Printer<'_>) -> String {
        let comment = if p.latex() { "% " } else { "" };
        let joints = |primes: &str| {
            let names: Vec<String> = (0..self.kinds.len())
                .map(|i| format!("{}{}{primes}", p.joint_letter(i), p.indices(&[i])))
                .collect();
            names.join(", ")
        };
        let mut lines = vec![
            format!("{}: equations of motion on a floating base, in Pinocchio's free-flyer conventions", self.name),
            format!("configuration q = [x, y, z, qx, qy, qz, qw, {}]: the base origin in world axes, the base's orientation as a quaternion, the joints", joints("")),
            format!("velocity v = [vx, vy, vz, ωx, ωy, ωz, {}]: the base origin's velocity and the base's angular velocity, both in base axes, then the joint rates", joints("'")),
            format!("acceleration a = [vx', vy', vz', ωx', ωy', ωz', {}], their time derivatives in the same coordinates", joints("''")),
            "gbx, gby, gbz: gravity in base axes, g_b = Rᵀ g (first below), the only way the quaternion enters; nothing reads the base position x, y, z".to_owned(),
            "Si = sin θi, Ci = cos θi, S12 = sin(θ1 + θ2), C12 = cos(θ1 + θ2), …".to_owned(),
        ];
        if self.offsets {
            lines.push("θi in Si, Ci includes the joint's constant offset where it is not a multiple of 90°".to_owned());
        }
        if self.mimics {
            lines.push("the coordinates are the joints but the mimic ones: a mimic joint follows joint j, sin(k qj + c), cos(k qj + c) its sine and cosine, k its multiplier, c its offset plus its own constant offset; its rows summed into joint j's with the factor k".to_owned());
        }
        if let Some(antecedents) = &self.antecedents {
            lines.push(format!(
                "a tree (Khalil-Kleinfinger's antecedents): {}",
                branches::describe(antecedents)
            ));
            let zeros: Vec<String> = branches::zero_inertia(antecedents)
                .iter()
                .map(|&(i, j)| {
                    let at = [i + BASE_COORDINATES, j + BASE_COORDINATES];
                    Label::new(Quantity::FloatingMass, &at).render(p)
                })
                .collect();
            if !zeros.is_empty() {
                lines.push(format!(
                    "zero, as their joints are on different branches (left out below): {}",
                    zeros.join(", ")
                ));
            }
        }
        let mut out = String::new();
        for line in lines {
            let _ = writeln!(out, "{comment}{line}");
        }
        out
    }
}
