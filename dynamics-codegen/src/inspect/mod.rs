//! Readable closed forms: the equations of motion printed as a person writes them, in the
//! notation of Niku ch. 6 (`T_i = Σ_j D_ij θj'' + I_i(act) θi'' + Σ_jk D_ijk θj' θk' + D_i`,
//! eqs. 6.43–6.46), as plain text or LaTeX. Plain text writes the book's dots as primes
//! (`θ1'`, `θ1''`), which read the same in a terminal and in rustdoc's code font.
//!
//! Each output of the [`Equations`] is expanded into its exact canonical polynomial, its
//! products of sines and cosines of joint angles folded back into those of sums
//! (`C1 C2 − S1 S2` → `C12`; both in [`crate::poly`]), then arranged for reading:
//!
//! * terms are grouped by their accelerations and velocities (`(…) θ1''`, `… θ1' θ2'`), and
//!   terms sharing a sine or cosine are grouped with their common parameters taken out
//!   (`(1/2 m1 + m2) g l1 C1`; `arrange`);
//! * each equation is named by a typed label (`D12`, `D11 + I1(act)`; `label`) and printed
//!   as text or LaTeX (`print`, `render`).
//!
//! The printer reads the polynomial's vocabulary ([`crate::poly::Sym`], a parameter, a joint
//! variable or the sine or cosine of a sum of joint angles), and prints the simplified models'
//! prunings (`simplified`, `simplified_report`).

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod arrange;
mod base_parameters;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod branches;
mod floating;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod label;
mod number;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod print;
mod render;
mod sections;
mod simplified;
mod simplified_report;

pub use crate::poly::Limits;
pub use base_parameters::render_base_parameters;
pub use floating::inspect_floating;
pub use print::Format;
pub use simplified::{inspect_simplified, Simplified};

use crate::algo::JointKind;
use crate::model::Robot;
use crate::poly::Expander;
use crate::trace::Equations;
use sections::Section;

/// The equations of motion of a robot, or its kinematics, ready to print.
pub struct Inspection {
    name: String,
    /// Whether these are the kinematics ([`inspect_kinematics`]).
    kinematics: bool,
    /// Whether these are a floating base's equations ([`inspect_floating`]).
    floating: bool,
    kinds: Vec<JointKind>,
    offsets: bool,
    /// Whether some joint follows another (a mimic joint's sines read like `sin(k q2 + c)`).
    mimics: bool,
    /// Each joint's antecedent, for a tree.
    antecedents: Option<Vec<Option<usize>>>,
    sections: Vec<Section>,
    limits: Limits,
}

/// Expands and arranges every output of `eq` within `limits`.
#[must_use]
pub fn inspect(eq: &Equations, robot: &Robot, limits: Limits) -> Inspection {
    let mut expander = Expander::new(eq, limits);
    let sections = sections::sections(&mut expander, eq, robot);
    Inspection::new(eq, robot, false, sections, limits)
}

/// The hand pose `[n o a p]` and the hand's Jacobians (in the base frame and ᴴJ), expanded and
/// arranged as [`inspect`] does the equations of motion: the book's chapter 3 forms
/// (`nx = C1 C23 …`).
#[must_use]
pub fn inspect_kinematics(eq: &Equations, robot: &Robot, limits: Limits) -> Inspection {
    let sections = sections::kinematic_sections(&mut Expander::new(eq, limits), eq);
    Inspection::new(eq, robot, true, sections, limits)
}

/// [`inspect`] and [`inspect_kinematics`] with one expansion, as the derive prints both: the
/// kinematics reuse the polynomials the equations of motion expanded (the joints' rotations
/// and positions), and each has a budget of `limits`, so the equations print as [`inspect`]
/// prints them.
#[must_use]
pub fn inspect_with_kinematics(
    eq: &Equations,
    robot: &Robot,
    limits: Limits,
) -> (Inspection, Inspection) {
    let mut expander = Expander::new(eq, limits);
    let dynamics = sections::sections(&mut expander, eq, robot);
    expander.renew_budget();
    let kinematics = sections::kinematic_sections(&mut expander, eq);
    (
        Inspection::new(eq, robot, false, dynamics, limits),
        Inspection::new(eq, robot, true, kinematics, limits),
    )
}

/// A part of the kinematics that prints on its own (in the rustdoc of its method).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KinematicPart {
    /// The hand pose `[n o a p]`.
    HandPose,
    /// The hand's Jacobian in the base frame.
    JacobianInBase,
    /// The hand's Jacobian in the hand frame, ᴴJ.
    JacobianInHand,
}

impl Inspection {
    fn new(
        eq: &Equations,
        robot: &Robot,
        kinematics: bool,
        sections: Vec<Section>,
        limits: Limits,
    ) -> Inspection {
        Inspection {
            name: robot.name.clone(),
            kinematics,
            floating: false,
            kinds: eq.kinds.clone(),
            offsets: eq.angle_offsets.iter().any(Option::is_some),
            mimics: robot.has_mimics(),
            antecedents: branches::antecedents(robot),
            sections,
            limits,
        }
    }

    /// Whether every equation fitted the limits.
    #[must_use]
    pub fn complete(&self) -> bool {
        self.sections
            .iter()
            .all(|s| s.entries.iter().all(|e| e.value.is_some()))
    }
}
