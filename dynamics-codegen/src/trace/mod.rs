//! The trace: the algorithms of [`crate::algo`] run on the symbolic scalar, turning a
//! [`Robot`] into the closed-form [`Equations`] in one shared expression graph.
//!
//! * `M(q)` by the composite rigid body algorithm, plus actuator inertia on the diagonal
//!   (`mass`);
//! * `g(q)` by Newton-Euler at rest or from the composite bodies' first moments, plus springs
//!   (`gravity`);
//! * `τ = M q̈ + C q̇ + g`, `C q̇` and `C q̇ + g` by recursive Newton-Euler, plus actuator inertia
//!   and springs (`newton_euler`);
//! * the kinetic and potential energy (`energy`);
//! * joint friction `f_v q̇ + f_c sign(q̇) + f_0`, added to `τ` (`friction`);
//! * the poses of the link frames and the hand, the hand's Jacobians, `J̇ q̇` and `Jᵀ F`
//!   (`kinematics`);
//! * the Christoffel symbols `Γ_ijk = ½(∂M_ij/∂q_k + ∂M_ik/∂q_j − ∂M_jk/∂q_i)` and
//!   `C_ij = Σ_k Γ_ijk q̇_k` (`coriolis`);
//! * the LDLᵀ of M, `M⁻¹` and `q̈ = M⁻¹(τ − C q̇ − g − f(q̇))` (`forward`);
//! * for a robot that asks for them, the opt-in families ([`Equations::add_families`]):
//!   `∂τ/∂q`, `∂τ/∂q̇` and `∂q̈/∂q`, `∂q̈/∂q̇`, `∂q̈/∂τ` (`derivatives`).
//!
//! `outputs` says which of these outputs each generated method returns.
//!
//! Where an output has several routes to the same value, each is traced and the one that
//! takes the fewest operations is kept (`cost`). Node ids follow the order in which the
//! graph is built, and the emitted code follows node ids: the steps run in a fixed order.

pub mod base_parameters;
mod coriolis;
mod cost;
mod derivatives;
mod energy;
mod expr;
mod floating;
mod floating_contacts;
mod floating_derivatives;
mod floating_kinematics;
mod floating_mimic;
mod floating_readable;
mod floating_regressor;
mod forward;
mod friction;
mod gravity;
mod joints;
mod kinematics;
mod lane_solve;
mod mass;
mod mimic;
mod newton_euler;
mod outputs;
mod regressor;
mod simplified;
mod tips;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod tracer;

use crate::algo::{JointKind, RobotScalars};
use crate::method::{Family, FamilySet};
use crate::model::Robot;
use crate::symbolic::{Graph, NodeId, Number};
use base_parameters::{BaseParameters, JointColumns};
use cost::matrix_ids;
pub use derivatives::DerivativeEquations;
pub use expr::Expr;
pub use floating::{derive_floating, BASE_COORDINATES, BASE_GRAVITY};
pub use floating_contacts::FloatingContactEquations;
pub use floating_kinematics::FloatingKinematicEquations;
pub use floating_readable::{derive_floating_readable, FloatingReadable};
pub use forward::ForwardEquations;
use joints::JointTerms;
pub use kinematics::KinematicEquations;
pub use outputs::{Shape, Solved};
pub use regressor::RegressorEquations;
pub use simplified::{Elements, Fallback, PrunedElement, SimplifiedEquations, SimplifiedOutput};
use std::cell::RefCell;
pub use tips::TipEquations;
use tracer::Tracer;

/// The closed-form equations of a robot: node ids into [`Equations::graph`].
#[derive(Clone, Debug)]
pub struct Equations {
    /// The shared expression graph.
    pub graph: Graph,
    /// Number of coordinates (of joints, but on a robot with mimic joints).
    pub dof: usize,
    /// Number of links, one per joint: `dof` but on a robot with mimic joints (the regressor's
    /// column blocks).
    pub links: usize,
    /// Struct fields, in the order of [`crate::symbolic::Var::Param`] indices.
    pub fields: Vec<String>,
    /// Joint kinds.
    pub kinds: Vec<JointKind>,
    /// For revolute joint i whose θ offset is not a multiple of π/2: the offset's node, so that
    /// [`crate::symbolic::Var::SinQ`]`(i)` is `sin(q_i + offset)`.
    pub angle_offsets: Vec<Option<NodeId>>,
    /// `M(q)`, n × n.
    pub mass: Vec<Vec<NodeId>>,
    /// `Γ_ijk` (= D_ijk) as `christoffel[i][j][k]`.
    pub christoffel: Vec<Vec<Vec<NodeId>>>,
    /// `C(q, q̇)`, n × n.
    pub coriolis: Vec<Vec<NodeId>>,
    /// `C(q, q̇) q̇`.
    pub coriolis_torques: Vec<NodeId>,
    /// `g(q)` with springs.
    pub gravity: Vec<NodeId>,
    /// `C q̇ + g`.
    pub bias: Vec<NodeId>,
    /// `τ = M q̈ + C q̇ + g`, plus friction.
    pub tau: Vec<NodeId>,
    /// Joint friction torques (zeros for a robot without friction).
    pub friction: Vec<NodeId>,
    /// Kinetic energy.
    pub kinetic_energy: NodeId,
    /// Potential energy.
    pub potential_energy: NodeId,
    /// Forward kinematics, Jacobians and statics.
    pub kinematics: KinematicEquations,
    /// The LDLᵀ of M, `M⁻¹` and the forward dynamics.
    pub forward: ForwardEquations,
    /// The families traced: every family but the opt-in ones, and those added
    /// ([`Equations::add_families`]).
    pub families: FamilySet,
    /// The derivatives of inverse and forward dynamics, where asked for
    /// ([`Equations::add_derivatives`]).
    pub derivatives: Option<DerivativeEquations>,
    /// The joint torque regressor and the standard parameters, where asked for
    /// ([`Equations::add_regressor`]).
    pub regressor: Option<RegressorEquations>,
    /// The base parameters of the joint parameters the description gives, where asked for
    /// and the geometry is numbers ([`Equations::base_parameters`]).
    pub base_parameters: Option<BaseParameters>,
    /// The pruned τ, M and g, where asked for and built by [`crate::simplify::add`].
    pub simplified: Option<SimplifiedEquations>,
    /// The kinematics of every tip, where asked for (every tree asks): [`Equations::add_tips`].
    pub tips: Option<TipEquations>,
}

impl Equations {
    /// Traces the opt-in families of `families` not traced yet for `robot` (the robot these
    /// equations are of), after every other output, in the table's order, so that the outputs
    /// traced before keep their nodes.
    /// A tree has its tips' kinematics whether it asks or not.
    pub fn add_families(&mut self, robot: &Robot, families: FamilySet) {
        let families = if robot.is_tree() {
            families.with(Family::Tips)
        } else {
            families
        };
        for family in families.opt_in() {
            if self.families.contains(family) {
                continue;
            }
            match family {
                Family::Derivatives => self.add_derivatives(),
                Family::Regressor => self.add_regressor(robot),
                Family::Tips => self.add_tips(robot),
                Family::BaseParameters => {
                    let joints: Vec<JointColumns> =
                        robot.joints.iter().map(JointColumns::described).collect();
                    // The regressor it traces is not emitted unless it was asked for too; the
                    // family is traced only where the geometry is numbers.
                    let asked = self.families;
                    self.base_parameters = self.base_parameters(robot, &joints);
                    self.families = match self.base_parameters {
                        Some(_) => asked.with(Family::BaseParameters),
                        None => asked,
                    };
                }
                // Built by the `simplify` stage, which needs the envelope and tolerances.
                Family::Simplified
                | Family::Dynamics
                | Family::Kinematics
                | Family::Forward
                | Family::Floating
                | Family::FloatingForward
                // A floating base's, traced by `Equations::add_floating_derivatives`,
                // `add_floating_regressor` and `floating_base_parameters`.
                | Family::FloatingDerivatives
                | Family::FloatingRegressor
                | Family::FloatingBaseParameters => {}
            }
        }
    }
}

/// Traces the equations of `robot`. The front end has checked the robot: every field exists and
/// the table is not empty.
#[must_use]
pub fn derive(robot: &Robot) -> Equations {
    let fields = robot.fields();
    let graph = RefCell::new(Graph::new());
    let mut tracer = Tracer::new(&graph, &fields, robot);
    let zero = tracer.num(Number::ZERO);
    let half = tracer.num(Number::ratio(1, 2).unwrap_or(Number::ONE));
    let chain = tracer.chain(robot);
    let (chain, mass) = mass::mass_matrix(&graph, &chain);
    let gravity = tracer.gravity(robot);
    let joints = JointTerms::new(&tracer, robot, zero);
    let mass = matrix_ids(&joints.with_actuator_inertia(mass));
    let gravity_torques = gravity::gravity(&graph, &chain, gravity, &joints);
    let newton_euler = newton_euler::newton_euler(&graph, &chain, gravity, &joints);
    let (kinetic_energy, potential_energy) = energy::energies(&chain, gravity, &joints, half);
    let (christoffel, coriolis) = coriolis::coriolis(&graph, &chain, &mass, &joints.qd, half.id());
    let kinematics = kinematics::kinematics(&mut tracer, robot, &joints.qd);
    let angle_offsets = tracer.angle_offsets();
    // Last, so that the nodes of a robot without friction are those it always had.
    let friction = friction::friction_torques(&tracer, robot, &joints.qd, joints.zero);
    let tau = with_friction(&mut graph.borrow_mut(), &newton_euler.tau, &friction);
    let mut joint_space = JointSpace {
        mass,
        christoffel,
        coriolis,
        coriolis_torques: newton_euler.coriolis_torques,
        gravity: gravity_torques,
        bias: newton_euler.bias,
        tau,
        friction,
        energies: [kinetic_energy, potential_energy],
        kinematics,
        angle_offsets,
        kinds: robot.joints.iter().map(|j| j.kind).collect(),
    };
    if robot.has_mimics() {
        let reduction = mimic::Reduction::new(&graph, &tracer, robot, &joint_space.angle_offsets);
        joint_space = joint_space.reduced(&reduction, &mut graph.borrow_mut());
    }
    let JointSpace {
        mass,
        christoffel,
        coriolis,
        coriolis_torques,
        gravity,
        bias,
        tau,
        friction,
        energies: [kinetic_energy, potential_energy],
        kinematics,
        angle_offsets,
        kinds,
    } = joint_space;
    // After τ, so that the nodes of the other outputs are those they always had.
    let forward = forward::forward(&graph, &mass, &bias, &friction, robot.is_tree());
    Equations {
        graph: graph.into_inner(),
        dof: mass.len(),
        links: robot.joints.len(),
        fields: fields.clone(),
        kinds,
        angle_offsets,
        mass,
        christoffel,
        coriolis,
        coriolis_torques,
        gravity,
        bias,
        tau,
        friction,
        kinetic_energy,
        potential_energy,
        kinematics,
        forward,
        families: FamilySet::default(),
        derivatives: None,
        regressor: None,
        base_parameters: None,
        simplified: None,
        tips: None,
    }
}

/// τ of the rigid bodies plus the friction torques, joint by joint.
fn with_friction(g: &mut Graph, rigid: &[NodeId], friction: &[NodeId]) -> Vec<NodeId> {
    rigid
        .iter()
        .zip(friction)
        .map(|(&t, &f)| g.add(t, f))
        .collect()
}

/// The outputs traced on every joint, before forward dynamics: those of the robot, or of its
/// joints when some are mimic joints, reduced to its coordinates ([`JointSpace::reduced`]).
struct JointSpace {
    mass: Vec<Vec<NodeId>>,
    christoffel: Vec<Vec<Vec<NodeId>>>,
    coriolis: Vec<Vec<NodeId>>,
    coriolis_torques: Vec<NodeId>,
    gravity: Vec<NodeId>,
    bias: Vec<NodeId>,
    tau: Vec<NodeId>,
    friction: Vec<NodeId>,
    energies: [NodeId; 2],
    kinematics: KinematicEquations,
    angle_offsets: Vec<Option<NodeId>>,
    kinds: Vec<JointKind>,
}

impl JointSpace {
    /// The same outputs in the coordinates of `reduction`.
    fn reduced(self, reduction: &mimic::Reduction, g: &mut Graph) -> JointSpace {
        let energies = reduction.substitute(g, &self.energies);
        JointSpace {
            mass: reduction.matrix(g, &self.mass),
            christoffel: reduction.christoffel(g, &self.christoffel),
            coriolis: reduction.matrix(g, &self.coriolis),
            coriolis_torques: reduction.vector(g, &self.coriolis_torques),
            gravity: reduction.vector(g, &self.gravity),
            bias: reduction.vector(g, &self.bias),
            tau: reduction.vector(g, &self.tau),
            friction: reduction.vector(g, &self.friction),
            energies: [energies[0], energies[1]],
            kinematics: reduction.kinematics(g, &self.kinematics),
            angle_offsets: reduction.of_coordinates(&self.angle_offsets),
            kinds: reduction.of_coordinates(&self.kinds),
        }
    }
}
