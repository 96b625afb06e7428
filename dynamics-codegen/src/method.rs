//! The typed table of the generated methods: for each, its name, arguments, result shape,
//! documentation, the book's equation and the names and docs of its output elements.
//!
//! The rows live in `dynamics-runtime/src/methods.rs` (symlinked here as `methods.rs`), which
//! the runtime's `Dynamics` trait and nalgebra wrappers are declared from, so the trait and the
//! generator cannot disagree. The one thing the runtime cannot say is which output of the
//! [`Equations`] a method returns: [`Method::shape`], an exhaustive `match`.

use crate::emit::Shape;
use crate::trace::Equations;

include!("methods.rs");

/// An argument of a generated method: `q`, `q̇` or `q̈`, each `&[T; N]`, or a wrench
/// `&[T; 6]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Argument {
    /// Joint positions.
    Q,
    /// Joint velocities.
    Qd,
    /// Joint accelerations.
    Qdd,
    /// A wrench `[fx, fy, fz, mx, my, mz]`.
    Wrench,
    /// Joint torques and forces.
    Tau,
}

impl Argument {
    /// The name the trait gives it: `q`, `qd`, `qdd`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Argument::Q => "q",
            Argument::Qd => "qd",
            Argument::Qdd => "qdd",
            Argument::Wrench => "wrench",
            Argument::Tau => "tau",
        }
    }
}

/// The shape of a method's result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Returns {
    /// `[[T; N]; N]`.
    Matrix,
    /// `[T; N]`.
    Vector,
    /// `T`.
    Scalar,
    /// `Pose<T>`: a rotation and a position.
    Pose,
    /// `[Pose<T>; N]`.
    Poses,
    /// `[[T; N]; 6]`: rows `[dx, dy, dz, δx, δy, δz]`, a column per joint.
    Jacobian,
    /// `[T; 6]`: a linear and an angular part.
    Spatial,
    /// `Result<[[T; N]; N], NotPositiveDefinite>`: a matrix solved with the LDLᵀ of M.
    SolvedMatrix,
    /// `Result<[T; N], NotPositiveDefinite>`: a vector solved with the LDLᵀ of M.
    SolvedVector,
    /// `InverseDynamicsDerivatives<[[T; N]; N]>`: `∂τ/∂q`, `∂τ/∂q̇`.
    InverseDerivatives,
    /// `Result<ForwardDynamicsDerivatives<[T; N], [[T; N]; N]>, NotPositiveDefinite>`: `q̈` and
    /// `∂q̈/∂q`, `∂q̈/∂q̇`, `∂q̈/∂τ`.
    ForwardDerivatives,
}

/// A family of methods, emitted in a module of its own with its own shared configuration and
/// motion functions, so that code calling one family's methods never inlines another's: a
/// controller that calls only `inverse_dynamics` compiles none of the kinematics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Family {
    /// M, C, g, τ, friction, energies.
    Dynamics,
    /// Poses, Jacobians, acceleration bias, statics.
    Kinematics,
    /// What solves with M through its LDLᵀ: forward dynamics, `M⁻¹`.
    Forward,
    /// The derivatives of inverse and forward dynamics: the opt-in trait
    /// `DynamicsDerivatives`, generated only for a robot that asks for it.
    Derivatives,
}

impl Family {
    /// Every family, in the order the derive emits their modules.
    pub const ALL: &'static [Family] = &[
        Family::Dynamics,
        Family::Kinematics,
        Family::Forward,
        Family::Derivatives,
    ];

    /// The runtime trait its methods belong to.
    #[must_use]
    pub fn trait_name(self) -> &'static str {
        match self {
            Family::Derivatives => "DynamicsDerivatives",
            Family::Dynamics | Family::Kinematics | Family::Forward => "Dynamics",
        }
    }

    /// Whether the derive writes it only for a robot that asks for it
    /// (`derivatives = true`).
    #[must_use]
    pub fn is_opt_in(self) -> bool {
        self == Family::Derivatives
    }

    /// Whether its module goes beside the struct, named after it, rather than in the derive's
    /// `const _` block: where it holds a method compiled apart ([`Method::is_compiled_apart`]),
    /// since a module inside that block shares the codegen unit of the code around it.
    #[must_use]
    pub fn is_beside_the_struct(self) -> bool {
        Method::ALL
            .iter()
            .any(|m| m.family() == self && m.is_compiled_apart())
    }

    /// The name of the module holding its generated functions.
    #[must_use]
    pub fn module(self) -> &'static str {
        match self {
            Family::Dynamics => "__dynamics",
            Family::Kinematics => "__kinematics",
            Family::Forward => "__forward",
            Family::Derivatives => "__derivatives",
        }
    }

    /// How `dynamics stats` names its shared functions: `(kinematic configuration)`.
    #[must_use]
    pub fn adjective(self) -> &'static str {
        match self {
            Family::Dynamics => "",
            Family::Kinematics => "kinematic ",
            Family::Forward => "forward ",
            Family::Derivatives => "derivatives' ",
        }
    }
}

/// The `Argument` of a row's argument name.
macro_rules! argument {
    (q) => {
        Argument::Q
    };
    (qd) => {
        Argument::Qd
    };
    (qdd) => {
        Argument::Qdd
    };
    (wrench) => {
        Argument::Wrench
    };
    (tau) => {
        Argument::Tau
    };
}

/// The `Returns` of a row's result shape.
macro_rules! returns {
    (matrix) => {
        Returns::Matrix
    };
    (vector) => {
        Returns::Vector
    };
    (scalar) => {
        Returns::Scalar
    };
    (pose) => {
        Returns::Pose
    };
    (poses) => {
        Returns::Poses
    };
    (jacobian) => {
        Returns::Jacobian
    };
    (spatial) => {
        Returns::Spatial
    };
    (solved_matrix) => {
        Returns::SolvedMatrix
    };
    (solved_vector) => {
        Returns::SolvedVector
    };
    (inverse_derivatives) => {
        Returns::InverseDerivatives
    };
    (forward_derivatives) => {
        Returns::ForwardDerivatives
    };
}

/// The `Family` of a row's family name.
macro_rules! family {
    (dynamics) => {
        Family::Dynamics
    };
    (kinematics) => {
        Family::Kinematics
    };
    (forward) => {
        Family::Forward
    };
    (derivatives) => {
        Family::Derivatives
    };
}

/// `enum Method` and its accessors from the table's rows.
macro_rules! declare_method {
    ($(
        $(#[doc = $doc:literal])*
        fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $_wrapper:ident {
            variant: $variant:ident,
            family: $family:ident,
            equation: $equation:expr,
            prefix: $prefix:literal,
            summary: $summary:literal,
            element: $element:literal,
            $(diagonal: $diagonal:literal,)?
            $(default: $default:ident,)?
        }
    )*) => {
        /// A method of the `Dynamics` trait.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum Method {
            $($(#[doc = $doc])* $variant,)*
        }

        impl Method {
            /// Every method, in the trait's order.
            pub const ALL: &'static [Method] = &[$(Method::$variant),*];

            /// Its name, e.g. `mass_matrix`.
            #[must_use]
            pub fn name(self) -> &'static str {
                match self { $(Method::$variant => stringify!($name),)* }
            }

            /// The generated module it goes to.
            #[must_use]
            pub fn family(self) -> Family {
                match self { $(Method::$variant => family!($family),)* }
            }

            /// Whether its function is compiled once, apart from the code that calls it:
            /// `#[inline(never)]`, in its family's module beside the struct, a codegen unit
            /// of its own, compiled in parallel with the rest. Only the largest, the forward
            /// dynamics' derivatives (tens of kilobytes, microseconds a call): the inverse
            /// dynamics' derivatives ran a half slower apart where the caller copied the
            /// result at once (`docs/design.md`).
            #[must_use]
            pub fn is_compiled_apart(self) -> bool {
                self == Method::ForwardDynamicsDerivatives
            }

            /// Its arguments, in order.
            #[must_use]
            pub fn arguments(self) -> &'static [Argument] {
                match self { $(Method::$variant => &[$(argument!($argument)),*],)* }
            }

            /// The shape of its result.
            #[must_use]
            pub fn returns(self) -> Returns {
                match self { $(Method::$variant => returns!($result),)* }
            }

            /// The trait method's documentation.
            #[must_use]
            pub fn doc(self) -> &'static str {
                match self { $(Method::$variant => concat!($($doc, "\n"),*),)* }
            }

            /// A one-line summary, e.g. `g(q), with joint springs.`
            #[must_use]
            pub fn summary(self) -> &'static str {
                match self { $(Method::$variant => $summary,)* }
            }

            /// The number of its equation in Niku, *Introduction to Robotics*, ch. 6.
            #[must_use]
            pub fn equation(self) -> Option<&'static str> {
                match self { $(Method::$variant => $equation,)* }
            }

            /// The prefix of its output elements' names (`m` gives `m1_2`, `tau` gives `tau3`).
            #[must_use]
            pub fn prefix(self) -> &'static str {
                match self { $(Method::$variant => $prefix,)* }
            }

            /// Whether the trait gives it a body (zeros), for a term a robot may not have: the
            /// derive then writes it only for a robot that has the term.
            #[must_use]
            pub fn has_default(self) -> bool {
                match self {
                    $(Method::$variant => None::<&str> $(.or(Some(stringify!($default))))?.is_some(),)*
                }
            }

            /// The doc template of an element, on the diagonal or not (`{i}`, `{j}`,
            /// `{equation}` to fill in).
            fn element_template(self, diagonal: bool) -> &'static str {
                match self {
                    $(Method::$variant => {
                        let on_diagonal: Option<&'static str> = None $(.or(Some($diagonal)))?;
                        match on_diagonal {
                            Some(template) if diagonal => template,
                            _ => $element,
                        }
                    })*
                }
            }
        }
    };
}

for_each_method!(declare_method);

impl Method {
    /// The outputs of `eq` it returns.
    #[must_use]
    pub fn shape(self, eq: &Equations) -> Shape<'_> {
        match self {
            Method::MassMatrix => Shape::Matrix(&eq.mass),
            Method::CoriolisMatrix => Shape::Matrix(&eq.coriolis),
            Method::CoriolisTorques => Shape::Vector(&eq.coriolis_torques),
            Method::GravityTorques => Shape::Vector(&eq.gravity),
            Method::BiasTorques => Shape::Vector(&eq.bias),
            Method::InverseDynamics => Shape::Vector(&eq.tau),
            Method::FrictionTorques => Shape::Vector(&eq.friction),
            Method::KineticEnergy => Shape::Scalar(eq.kinetic_energy),
            Method::PotentialEnergy => Shape::Scalar(eq.potential_energy),
            Method::HandPose => Shape::Matrix(&eq.kinematics.hand_pose),
            Method::LinkPoses => Shape::Stack(&eq.kinematics.link_poses),
            Method::HandJacobianInBase => Shape::Matrix(&eq.kinematics.jacobian_in_base),
            Method::HandJacobianInHand => Shape::Matrix(&eq.kinematics.jacobian_in_hand),
            Method::HandAccelerationBiasInBase => Shape::Vector(&eq.kinematics.bias_in_base),
            Method::HandAccelerationBiasInHand => Shape::Vector(&eq.kinematics.bias_in_hand),
            Method::JointTorquesForHandWrench => {
                Shape::Vector(&eq.kinematics.torques_for_hand_wrench)
            }
            Method::JointTorquesForBaseWrench => {
                Shape::Vector(&eq.kinematics.torques_for_base_wrench)
            }
            Method::MassMatrixInverse => Shape::SolvedMatrix {
                pivots: &eq.forward.factors.pivots,
                matrix: &eq.forward.mass_inverse,
            },
            Method::ForwardDynamics => Shape::SolvedVector {
                pivots: &eq.forward.factors.pivots,
                vector: &eq.forward.qdd,
            },
            Method::InverseDynamicsDerivatives => {
                Shape::Stack(eq.derivatives.as_ref().map_or(&[], |d| &d.inverse))
            }
            Method::ForwardDynamicsDerivatives => Shape::SolvedStack {
                pivots: &eq.forward.factors.pivots,
                vector: eq.derivatives.as_ref().map_or(&[], |d| &d.qdd),
                stack: eq.derivatives.as_ref().map_or(&[], |d| &d.forward),
            },
        }
    }

    /// Whether the derive writes it for these equations: a method the trait gives a body
    /// of zeros (friction) only where its result is not zero, an opt-in family's only where
    /// the robot asked for it.
    #[must_use]
    pub fn is_generated(self, eq: &Equations) -> bool {
        if self.family().is_opt_in() && eq.derivatives.is_none() {
            return false;
        }
        !self.has_default()
            || self
                .shape(eq)
                .outputs()
                .iter()
                .any(|&id| !eq.graph.is_zero(id))
    }

    /// The method called `name`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Method> {
        Method::ALL.iter().copied().find(|m| m.name() == name)
    }

    /// What element `(i, j)` (from 0; `j` 0 for a vector, both for a scalar) is, in the
    /// book's terms: short and ASCII, since a large robot has a hundred of them and non-ASCII
    /// text is escaped in tokens.
    #[must_use]
    pub fn describe(self, i: usize, j: usize) -> String {
        self.describe_in(0, i, j)
    }

    /// [`Method::describe`] of element `(i, j)` of the `k`-th matrix (from 0) of a stack of
    /// them (`link_poses`).
    #[must_use]
    pub fn describe_in(self, k: usize, i: usize, j: usize) -> String {
        let diagonal = self.returns() == Returns::Matrix && i == j;
        self.element_template(diagonal)
            .replace("{k}", &(k + 1).to_string())
            .replace("{i}", &(i + 1).to_string())
            .replace("{j}", &(j + 1).to_string())
            .replace("{x}", self.arguments().get(k).map_or("", |a| a.name()))
            .replace("{equation}", self.equation().unwrap_or_default())
    }
}

#[cfg(test)]
mod tests {
    use super::{Method, Returns};

    #[test]
    fn elements_are_described_in_the_books_terms() {
        let table = [
            (Method::MassMatrix, 0, 1, "D12 = D21 (6.43)"),
            (Method::MassMatrix, 2, 2, "D33 (6.43) + actuator inertia"),
            (
                Method::CoriolisMatrix,
                1,
                0,
                "C21 = sum of D21k qd_k (6.44)",
            ),
            (
                Method::CoriolisTorques,
                3,
                0,
                "centripetal and Coriolis torque 4",
            ),
            (
                Method::GravityTorques,
                2,
                0,
                "D3 (6.45), gravity and spring",
            ),
            (
                Method::BiasTorques,
                0,
                0,
                "centripetal, Coriolis and gravity torque 1",
            ),
            (Method::InverseDynamics, 2, 0, "T3 (6.46)"),
            (Method::FrictionTorques, 1, 0, "friction torque 2"),
            (Method::PotentialEnergy, 0, 0, "potential energy"),
        ];
        for (method, i, j, text) in table {
            assert_eq!(method.describe(i, j), text);
        }
    }

    #[test]
    fn every_method_is_complete() {
        for &m in Method::ALL {
            assert_eq!(Method::from_name(m.name()), Some(m));
            assert!(!m.doc().is_empty() && !m.summary().is_empty(), "{m:?}");
            // Every method but friction's reads q.
            let reads_q = m.arguments().first() == Some(&super::Argument::Q);
            assert_eq!(reads_q, m != Method::FrictionTorques, "{m:?}");
            let template = [m.element_template(false), m.element_template(true)];
            let cites = template.iter().any(|t| t.contains("{equation}"));
            assert!(!cites || m.equation().is_some(), "{m:?} cites no equation");
            let indexed = |key| template.iter().all(|t| t.contains(key));
            assert_eq!(indexed("{i}"), m.returns() != Returns::Scalar, "{m:?}");
        }
    }
}
