//! The door's readable equations: a loaded robot's equations of motion, its kinematics, its
//! base parameters or its simplified models in the book's notation, as text or LaTeX (what
//! `dynamics inspect` prints and the Python package's `Robot.equations` returns).

use super::{Diagnostic, Loaded};
use crate::inspect::{
    inspect, inspect_floating, inspect_kinematics, inspect_simplified, inspect_with_kinematics,
    render_base_parameters, Format, KinematicPart, Limits,
};
use crate::model::{Robot, Simplification};
use crate::trace::base_parameters::JointColumns;
use crate::trace::derive;
use crate::trace::Equations;

/// Which of a robot's equations to print.
#[derive(Clone, Copy, Debug)]
pub enum Readable<'a> {
    /// The equations of motion: M, C and g (Niku, eqs. 6.43–6.46).
    Motion,
    /// The hand pose and the hand's Jacobians.
    Kinematics,
    /// The base parameters, with these joints' parameters (rotor inertia, friction) beside the
    /// links', one entry per joint.
    BaseParameters(&'a [JointColumns]),
    /// τ, M, C q̇ and g pruned within these models' proven bounds.
    Simplified(&'a Simplification),
}

impl Loaded {
    /// The equations `what` of the robot, as `format` writes them.
    ///
    /// # Errors
    /// Base parameters of a robot whose lengths or angles are parameters, or simplified models
    /// that cannot be built (`file: message`).
    pub fn readable(&self, what: Readable<'_>, format: Format) -> Result<String, Diagnostic> {
        let robot = &self.robot;
        let mut eq = derive(robot);
        match what {
            Readable::Motion => Ok(inspect(&eq, robot, Limits::UNBOUNDED).render(format)),
            Readable::Kinematics => {
                Ok(inspect_kinematics(&eq, robot, Limits::UNBOUNDED).render(format))
            }
            Readable::BaseParameters(columns) => {
                let message = "the base parameters need the robot's lengths and angles as \
                               numbers, not struct fields";
                let base = eq.base_parameters(robot, columns).ok_or_else(|| {
                    Diagnostic::of_file(&self.path, message).with_help(
                        "they group the links' parameters by the lengths and angles: give \
                         those as numbers in the description (masses and inertias may stay \
                         parameters)",
                    )
                })?;
                Ok(render_base_parameters(&robot.name, &base, format))
            }
            Readable::Simplified(request) => {
                let simplified = inspect_simplified(&eq, robot, request)
                    .map_err(|e| Diagnostic::of_file(&self.path, e))?;
                Ok(simplified.render(format))
            }
        }
    }
}

impl Loaded {
    /// The equations of motion of the robot on a free-flying base (`base = floating`): `M`, `h`,
    /// `g` and `τ` in Pinocchio's coordinates, gravity in base axes `g_b` from the quaternion
    /// first, as `format` writes them.
    ///
    /// # Errors
    /// As [`Loaded::floating_equations`]: a description file without a `[floating]` table, a
    /// URDF whose body cannot be read, what a floating base does not support yet.
    pub fn floating_readable(&self, format: Format) -> Result<String, Vec<Diagnostic>> {
        // The same checks, and what the derive would refuse, as the emitted equations'.
        let flyer = self.floating_flyer()?;
        let readable = crate::trace::derive_floating_readable(&self.robot, flyer);
        Ok(inspect_floating(&readable, &self.robot, FLOATING_LIMITS).render(format))
    }
}

/// The floating printout's bound, for all its equations together: Solo 12's and ANYmal B's take
/// under a second; unbounded, the G1's (29 joints) had taken 23 GB of memory when it was stopped
/// after 400 s, its τ's expanded terms multiplying leg by arm.
const FLOATING_LIMITS: Limits = Limits {
    max_terms: 200_000,
    max_work: 20_000_000,
};

/// What the derive adds to the code for the readable equations (`EQUATIONS`,
/// `EQUATIONS_LATEX`) and the kinematic methods' rustdoc, within its limits.
#[derive(Clone, Copy, Debug)]
pub struct DerivedReadable {
    /// Bytes of the text equations.
    pub text: usize,
    /// Bytes of the LaTeX equations.
    pub latex: usize,
    /// Whether they are whole (not capped: some sections then point to `dynamics inspect`).
    pub complete: bool,
    /// Bytes of the kinematic methods' rustdoc.
    pub docs: usize,
    /// Whether the rustdoc is whole.
    pub docs_complete: bool,
}

/// The readable equations the derive adds for `eq` of `robot` (`dynamics stats` times it).
#[must_use]
pub fn derived_readable(eq: &Equations, robot: &Robot) -> DerivedReadable {
    let (inspection, kinematics) = inspect_with_kinematics(eq, robot, Limits::DERIVE);
    let parts = [
        KinematicPart::HandPose,
        KinematicPart::JacobianInBase,
        KinematicPart::JacobianInHand,
    ];
    let docs = parts
        .iter()
        .filter_map(|&part| kinematics.render_part(part, Format::Text))
        .map(|doc| doc.len())
        .sum();
    DerivedReadable {
        text: inspection.render(Format::Text).len(),
        latex: inspection.render(Format::Latex).len(),
        complete: inspection.complete(),
        docs,
        docs_complete: kinematics.complete(),
    }
}
