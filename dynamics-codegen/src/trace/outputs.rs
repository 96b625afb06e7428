//! Where a method's result lies in the traced graph: its [`Shape`], which output of the
//! [`Equations`] each method returns ([`Method::shape`]), and whether the derive writes it.

use super::{Elements, Equations, TipEquations};
use crate::method::Method;
use crate::symbolic::{NodeId, Tangents};

/// The nodes of a method's result, as the graph holds them.
#[derive(Clone, Copy)]
pub enum Shape<'a> {
    /// A scalar.
    Scalar(NodeId),
    /// A vector.
    Vector(&'a [NodeId]),
    /// A matrix, rows first.
    Matrix(&'a [Vec<NodeId>]),
    /// Matrices, one after the other.
    Stack(&'a [Vec<Vec<NodeId>>]),
    /// Matrices, one after the other, each from its nodes or, where `lanes`
    /// has a plan and the build computes tangents in lanes, from the plan's lanes (row i
    /// the tangent of output i).
    Lanes {
        /// The matrices as nodes, rows first.
        stack: &'a [Vec<Vec<NodeId>>],
        /// Per matrix, the plan computing it in lanes, if any.
        lanes: &'a [Option<Tangents>],
        /// For matrices through the LDLᵀ of M (`∂q̈`), its pivots and the vector returned
        /// beside them, `Some((vector, [matrices]))` where every pivot is positive.
        solved: Option<Solved<'a>>,
    },
    /// A vector through the LDLᵀ of M, `Some` where every pivot is positive.
    SolvedVector {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The vector.
        vector: &'a [NodeId],
    },
    /// A matrix through the LDLᵀ of M, `Some` where every pivot is positive.
    SolvedMatrix {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The matrix, rows first.
        matrix: &'a [Vec<NodeId>],
    },
    /// A vector and matrices through the LDLᵀ of M, `Some((vector, [matrices]))` where every
    /// pivot is positive.
    SolvedStack {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The vector.
        vector: &'a [NodeId],
        /// The matrices, rows first.
        stack: &'a [Vec<Vec<NodeId>>],
    },
}

/// The part of a [`Shape::Lanes`] through the LDLᵀ of M, as in [`Shape::SolvedStack`].
#[derive(Clone, Copy)]
pub struct Solved<'a> {
    /// The pivots.
    pub pivots: &'a [NodeId],
    /// The vector.
    pub vector: &'a [NodeId],
}

impl Solved<'_> {
    /// The pivots, then the vector.
    fn nodes(&self) -> impl Iterator<Item = NodeId> + '_ {
        self.pivots.iter().chain(self.vector).copied()
    }
}

impl Shape<'_> {
    /// The nodes a function computing it in lanes reads: the plans' factors and the matrices
    /// without a plan (the other shapes' elements).
    pub fn lane_outputs(&self) -> Vec<NodeId> {
        let Shape::Lanes {
            stack,
            lanes,
            solved,
        } = self
        else {
            return self.outputs();
        };
        let factors = lanes.iter().flatten().flat_map(Tangents::factors);
        let unplanned = stack.iter().zip(*lanes).filter(|(_, plan)| plan.is_none());
        let nodes = unplanned.flat_map(|(m, _)| m.iter().flatten().copied());
        let solved = solved.iter().flat_map(Solved::nodes);
        solved.chain(nodes).chain(factors).collect()
    }

    /// The same result computed from its nodes alone (itself for the other shapes).
    #[must_use]
    pub fn scalar(&self) -> Self {
        match *self {
            Shape::Lanes {
                stack,
                solved: None,
                ..
            } => Shape::Stack(stack),
            Shape::Lanes {
                stack,
                solved: Some(Solved { pivots, vector }),
                ..
            } => Shape::SolvedStack {
                pivots,
                vector,
                stack,
            },
            shape => shape,
        }
    }

    /// Its elements, rows first.
    pub fn outputs(&self) -> Vec<NodeId> {
        match self {
            Shape::Scalar(id) => vec![*id],
            Shape::Vector(v) => v.to_vec(),
            Shape::Matrix(m) => m.iter().flatten().copied().collect(),
            Shape::Stack(s) => s.iter().flatten().flatten().copied().collect(),
            // Both routes' nodes: the code chooses by the scalar type (`Real::TANGENTS_IN_LANES`).
            Shape::Lanes {
                stack,
                lanes,
                solved,
            } => {
                let factors = lanes.iter().flatten().flat_map(Tangents::factors);
                let nodes = stack.iter().flatten().flatten().copied();
                let solved = solved.iter().flat_map(Solved::nodes);
                solved.chain(nodes).chain(factors).collect()
            }
            Shape::SolvedVector { pivots, vector } => {
                pivots.iter().chain(*vector).copied().collect()
            }
            Shape::SolvedMatrix { pivots, matrix } => {
                let elements = matrix.iter().flatten();
                pivots.iter().chain(elements).copied().collect()
            }
            Shape::SolvedStack {
                pivots,
                vector,
                stack,
            } => {
                let elements = stack.iter().flatten().flatten();
                let values = vector.iter().chain(elements);
                pivots.iter().chain(values).copied().collect()
            }
        }
    }
}

/// `∂q̈` with `q̈` through the LDLᵀ of M: in lanes where planned.
fn forward_derivatives(eq: &Equations) -> Shape<'_> {
    let pivots = &eq.forward.factors.pivots;
    match &eq.derivatives {
        Some(d) if d.forward_lanes.iter().any(Option::is_some) => Shape::Lanes {
            stack: &d.forward,
            lanes: &d.forward_lanes,
            solved: Some(Solved {
                pivots,
                vector: &d.qdd,
            }),
        },
        d => Shape::SolvedStack {
            pivots,
            vector: d.as_ref().map_or(&[], |d| &d.qdd),
            stack: d.as_ref().map_or(&[], |d| &d.forward),
        },
    }
}

/// The tips of a robot whose tips were not traced.
static NO_TIPS: TipEquations = TipEquations::NONE;

impl Method {
    /// The outputs of `eq` it returns.
    #[must_use]
    pub fn shape(self, eq: &Equations) -> Shape<'_> {
        match self {
            Method::MassMatrix | Method::FloatingMassMatrix => Shape::Matrix(&eq.mass),
            Method::CoriolisMatrix => Shape::Matrix(&eq.coriolis),
            Method::CoriolisTorques => Shape::Vector(&eq.coriolis_torques),
            Method::GravityTorques | Method::FloatingGravity => Shape::Vector(&eq.gravity),
            Method::BiasTorques | Method::FloatingBiasForces => Shape::Vector(&eq.bias),
            Method::InverseDynamics | Method::FloatingInverseDynamics => Shape::Vector(&eq.tau),
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
            Method::MassMatrixInverse | Method::FloatingMassMatrixInverse => Shape::SolvedMatrix {
                pivots: &eq.forward.factors.pivots,
                matrix: &eq.forward.mass_inverse,
            },
            Method::ForwardDynamics | Method::FloatingForwardDynamics => Shape::SolvedVector {
                pivots: &eq.forward.returned.1,
                vector: &eq.forward.returned.0,
            },
            Method::InverseDynamicsDerivatives | Method::FloatingInverseDynamicsDerivatives => {
                match &eq.derivatives {
                    Some(d) if d.inverse_lanes.iter().any(Option::is_some) => Shape::Lanes {
                        stack: &d.inverse,
                        lanes: &d.inverse_lanes,
                        solved: None,
                    },
                    d => Shape::Stack(d.as_ref().map_or(&[], |d| &d.inverse)),
                }
            }
            Method::Regressor
            | Method::JointRegressor
            | Method::JointParameters
            | Method::StandardParameters
            | Method::BaseRegressor
            | Method::BaseParameters
            | Method::BaseFromStandard
            | Method::BaseFromJoints
            | Method::FloatingRegressor
            | Method::FloatingStandardParameters
            | Method::FloatingBaseRegressor
            | Method::FloatingBaseParameters
            | Method::FloatingBaseFromStandard => self.identification_shape(eq),
            Method::InverseDynamicsSimplified
            | Method::MassMatrixSimplified
            | Method::CoriolisTorquesSimplified
            | Method::GravityTorquesSimplified => {
                match eq.simplified.as_ref().and_then(|s| s.output(self)) {
                    Some(o) => match &o.elements {
                        Elements::Vector(v) => Shape::Vector(v),
                        Elements::Matrix(m) => Shape::Matrix(m),
                    },
                    None if self == Method::MassMatrixSimplified => Shape::Matrix(&[]),
                    None => Shape::Vector(&[]),
                }
            }
            Method::ForwardDynamicsDerivatives | Method::FloatingForwardDynamicsDerivatives => {
                forward_derivatives(eq)
            }
            Method::TipPoses
            | Method::TipJacobiansInBase
            | Method::TipJacobiansInTip
            | Method::TipAccelerationBiasesInBase
            | Method::TipAccelerationBiasesInTip
            | Method::JointTorquesForTipWrenches
            | Method::JointTorquesForTipWrenchesInBase => {
                eq.tips.as_ref().unwrap_or(&NO_TIPS).shape(self)
            }
        }
    }

    /// The result of a method of the regressor or base parameters (which [`Method::shape`]
    /// sends here).
    fn identification_shape(self, eq: &Equations) -> Shape<'_> {
        match self {
            Method::Regressor | Method::FloatingRegressor => {
                Shape::Stack(eq.regressor.as_ref().map_or(&[], |r| &r.columns))
            }
            Method::JointRegressor => {
                Shape::Matrix(eq.regressor.as_ref().map_or(&[], |r| &r.joint_columns))
            }
            Method::JointParameters => {
                Shape::Matrix(eq.regressor.as_ref().map_or(&[], |r| &r.joint_parameters))
            }
            Method::StandardParameters | Method::FloatingStandardParameters => {
                Shape::Matrix(eq.regressor.as_ref().map_or(&[], |r| &r.parameters))
            }
            Method::BaseRegressor | Method::FloatingBaseRegressor => {
                Shape::Matrix(eq.base_parameters.as_ref().map_or(&[], |b| &b.regressor))
            }
            Method::BaseParameters | Method::FloatingBaseParameters => {
                Shape::Vector(eq.base_parameters.as_ref().map_or(&[], |b| &b.values))
            }
            Method::BaseFromStandard | Method::FloatingBaseFromStandard => {
                Shape::Stack(eq.base_parameters.as_ref().map_or(&[], |b| &b.link_map))
            }
            // `BaseFromJoints`, the last of them.
            _ => Shape::Stack(eq.base_parameters.as_ref().map_or(&[], |b| &b.joint_map)),
        }
    }

    /// Whether the derive writes it for these equations: a method the trait gives a body
    /// of zeros (friction) only where its result is not zero, an opt-in family's only where
    /// the robot asked for it.
    #[must_use]
    pub fn is_generated(self, eq: &Equations) -> bool {
        if !eq.families.has(self) {
            return false;
        }
        !self.has_default()
            || self
                .shape(eq)
                .outputs()
                .iter()
                .any(|&id| !eq.graph.is_zero(id))
    }
}
