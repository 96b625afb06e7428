//! The names of the printed equations: which quantity (`D`, `C`, `T`), of which joints, and
//! whether the actuator inertia is added (`D11 + I1(act)`).

use super::print::Printer;

/// A quantity of the equations of motion, each printed in its own section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum Quantity {
    /// The inertia `D_ij` (eq. 6.43).
    Inertia,
    /// The centripetal and Coriolis coefficient `D_ijk` (eq. 6.44).
    Christoffel,
    /// The Coriolis matrix `C_ij`.
    Coriolis,
    /// The centripetal and Coriolis torque `(C q̇)_i`, the simplified models' (`C1`).
    CoriolisTorque,
    /// The gravity torque `D_i` (eq. 6.45).
    Gravity,
    /// The joint friction torque `F_i`, part of `T_i`.
    Friction,
    /// The joint torque or force `T_i` (eq. 6.46).
    Torque,
    /// An entry of the hand pose `[n o a p]` (`nx`, …, `pz`; joints = [row, column]).
    HandPose,
    /// The hand's Jacobian in the base frame, `J_ij` (row i of dx … δz, joint j).
    JacobianInBase,
    /// The book's ᴴJ, the hand's Jacobian in the hand frame (eq. 6.64).
    JacobianInHand,
    /// A floating base's gravity in base axes, `g_b = Rᵀ g` (joints = [axis]).
    BaseGravity,
    /// A floating base's mass matrix `M` (joints = two coordinates of `v`).
    FloatingMass,
    /// A floating base's bias `h = C v + g` (joints = [coordinate]).
    FloatingBias,
    /// A floating base's generalized gravity `g`.
    FloatingGravity,
    /// A floating base's inverse dynamics `τ = M a + h`.
    FloatingTorque,
}

impl Quantity {
    /// The letter of its name in the book.
    fn letter(self, latex: bool) -> &'static str {
        match self {
            Quantity::Inertia | Quantity::Christoffel | Quantity::Gravity => "D",
            Quantity::Coriolis | Quantity::CoriolisTorque => "C",
            Quantity::Friction => "F",
            Quantity::Torque => "T",
            Quantity::HandPose => "", // named per entry (`nx`) by `Label::render`
            Quantity::JacobianInBase => "J",
            Quantity::JacobianInHand if latex => "{}^{H}J",
            Quantity::JacobianInHand => "ᴴJ",
            // Named by their coordinates (`M[vx, θ1]`) by `super::floating`.
            Quantity::BaseGravity
            | Quantity::FloatingMass
            | Quantity::FloatingBias
            | Quantity::FloatingGravity
            | Quantity::FloatingTorque => "",
        }
    }

    /// The title of its section.
    pub(super) fn heading(self) -> &'static str {
        match self {
            Quantity::Inertia => "Inertia D_ij (eq. 6.43); M = D with the actuator inertia I_i(act) on the diagonal (6.39)",
            Quantity::Christoffel => "Centripetal and Coriolis coefficients D_ijk (eq. 6.44; D_ijk = D_ikj)",
            Quantity::Coriolis => "Coriolis matrix C_ij = Σ_k D_ijk θ_k'",
            Quantity::CoriolisTorque => "Centripetal and Coriolis torques C_i = Σ_jk D_ijk θ_j' θ_k' (C θ')",
            Quantity::Gravity => "Gravity D_i (eq. 6.45), with joint springs",
            Quantity::Friction => "Joint friction F_i, in T_i: viscous θi', Coulomb sgn(θi') (0 at rest) or tanh(θi'/εi) (εi: joint i's smoothing velocity), offset",
            Quantity::Torque => "Joint torques and forces T_i (eq. 6.46)",
            Quantity::HandPose => "Hand pose, the base frame's T_H = A1 ⋯ An (and the tool) = [n o a p]: rotation columns n, o, a and position p",
            Quantity::JacobianInBase => "Hand Jacobian J_ij in the base frame: rows i = dx, dy, dz, δx, δy, δz (the hand's velocity and angular velocity), column j = joint j",
            Quantity::JacobianInHand => "Hand Jacobian ᴴJ_ij in the hand frame (eq. 6.64): rows i = dx, dy, dz, δx, δy, δz in the hand's axes, column j = joint j",
            Quantity::BaseGravity => "Gravity in base axes g_b = Rᵀ g, R the quaternion's matrix (a polynomial of qx, qy, qz, qw, not normalised, as Pinocchio reads it), g gravity in world axes",
            Quantity::FloatingMass => "Mass matrix M[a, b] = M[b, a] (Pinocchio's crba), rows and columns in v's order",
            Quantity::FloatingBias => "Bias h = C(q, v) v + g(q) (Pinocchio's nonLinearEffects)",
            Quantity::FloatingGravity => "Generalized gravity g(q) (Pinocchio's computeGeneralizedGravity)",
            Quantity::FloatingTorque => "Inverse dynamics τ = M(q) a + h(q, v) (Pinocchio's rnea): rows vx … ωz the wrench on the base [fx, fy, fz, mx, my, mz] in base axes, about its origin; then the joint torques",
        }
    }
}

/// The name of one printed equation: `D12`, `D112`, `T1`, `D11 + I1(act)`.
#[derive(Clone, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Label {
    quantity: Quantity,
    /// 0-based joint indices.
    joints: Vec<usize>,
    /// Whether the actuator inertia of the first joint is added (the diagonal of M).
    actuator_inertia: bool,
}

impl Label {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn new(quantity: Quantity, joints: &[usize]) -> Label {
        Label {
            quantity,
            joints: joints.to_vec(),
            actuator_inertia: false,
        }
    }

    /// The same name with the actuator inertia added.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn with_actuator_inertia(self) -> Label {
        Label {
            actuator_inertia: true,
            ..self
        }
    }

    /// The name as `printer` writes it.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn render(&self, printer: &Printer<'_>) -> String {
        if let Some(name) = printer.floating_label(self.quantity, &self.joints) {
            return name;
        }
        if self.quantity == Quantity::HandPose {
            // The book's `n_x` … `p_z`: column letter, row axis.
            let column = ["n", "o", "a", "p"][self.joints[1]];
            let row = ["x", "y", "z"][self.joints[0]];
            let sep = if printer.latex() { "_" } else { "" };
            return format!("{column}{sep}{row}");
        }
        let name = format!(
            "{}{}",
            self.quantity.letter(printer.latex()),
            printer.indices(&self.joints)
        );
        if !self.actuator_inertia {
            return name;
        }
        let act = if printer.latex() {
            "\\mathrm{act}"
        } else {
            "act"
        };
        format!("{name} + I{}({act})", printer.indices(&self.joints[..1]))
    }
}
