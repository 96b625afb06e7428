//! Independent numeric reference for the dynamics of serial robots and kinematic trees
//! described by a Denavit–Hartenberg table (Khalil and Kleinfinger's for trees) or by URDF-style
//! joint placements.
//!
//! This crate is a direct, deliberately plain implementation of the method of
//! S. B. Niku, *Introduction to Robotics*, chapter 6 ("Dynamic and Force Analysis"):
//! Lagrangian mechanics written with 4×4 homogeneous matrices. Every quantity is
//! evaluated numerically in `f64` with [`nalgebra`], following the book's equations
//! one by one:
//!
//! * the link matrices `A_i` and their derivatives `∂A_i/∂q_i = Q_i A_i`
//!   (eqs. 6.21–6.27),
//! * `U_ij = ∂ ⁰T_i/∂q_j` and `U_ijk = ∂U_ij/∂q_k` (eqs. 6.28, 6.29),
//! * the pseudo-inertia matrix `J_i` (eqs. 6.36, 6.37),
//! * the kinetic energy (eq. 6.39) and the potential energy (the equation that
//!   follows 6.39; its number is lost in the text extraction of the chapter),
//! * the coefficients `D_ij`, `D_ijk`, `D_i` (eqs. 6.43–6.45) and the joint
//!   torques `T_i` (eq. 6.46),
//! * and, in [`statics`], the static force relations `T = Jᵀ F` (eq. 6.64) and the
//!   equivalent force/moment in another frame (eq. 6.73).
//!
//! # Trees
//!
//! Joint `i` hangs off its antecedent `a(i)` ([`Joint::parent`], an earlier joint, or the
//! base; by default the joint before, as in a chain), and `⁰T_i = ⁰T_{a(i)} A_i`: the product
//! of the `A`s along the path from the base to link `i` ([`Robot::path`]). Write `j ≼ p` for
//! "joint `j` is `p` or an ancestor of `p`" ([`Robot::moves`]); in a chain `j ≼ p` is `j ≤ p`,
//! and every sum below is the book's.
//!
//! * Modified convention (Khalil and Kleinfinger 1986):
//!   `A_i = Rotz(γ_i) Transz(b_i) Rotx(α_i) Transx(a_i) Rotz(θ_i) Transz(d_i)`, with
//!   `γ = b = 0` by default. The standard convention describes chains only.
//! * URDF style ([`Convention::Urdf`], [`Placement`]): `A_i = X_i Rot(axis_i, q_i)` or
//!   `X_i Trans(axis_i q_i)`, whose `Q_i` is `[[axis_i]×, 0; 0, 0]` or `[0, axis_i; 0, 0]`
//!   ([`axis_q_matrix`]); [`Robot::from_pinocchio_model`] reads a Pinocchio model's record so.
//! * `U_ij = ∂ ⁰T_i/∂q_j` is the path's product with `A_j` differentiated if `j ≼ i`, zero
//!   otherwise; `U_ijk` likewise with `j, k ≼ i`.
//! * `D_ij = Σ_{p: i ≼ p, j ≼ p} Tr(U_pj J_p U_piᵀ)` (zero when neither of `i`, `j` is an
//!   ancestor of the other), `D_ijk = Σ_{p: i, j, k ≼ p} Tr(U_pjk J_p U_piᵀ)`,
//!   `D_i = −Σ_{p: i ≼ p} m_p gᵀ U_pi r̄_p`,
//!   `K = ½ Σ_i Σ_{p ≼ i} Σ_{r ≼ i} Tr(U_ip J_i U_irᵀ) q̇_p q̇_r`, `P = −Σ_i m_i gᵀ ⁰T_i r̄_i`.
//! * Kinematics of any link ([`Robot::frame`], [`Robot::frame_jacobian`], whose column `j` is
//!   zero unless `j ≼ i`) and statics per link as in a chain.
//!
//! # For tests only
//!
//! The method costs O(n⁴) matrix products per evaluation (the triple and quadruple
//! sums of traces of 4×4 products) and recomputes every matrix product from scratch.
//! That is the point: the code is meant to be *obviously* the book's method so that it
//! can serve as an independent check of the project's code generator. It shares no
//! code with the generator. Do not use it in a controller.
//!
//! # Indexing
//!
//! The book numbers joints, links and frames from 1: joint `i` moves link `i`, whose
//! frame is `i`, and `⁰T_i = A_1 A_2 ⋯ A_i`. **This API numbers them from 0**: the
//! argument `i` of every function denotes the book's joint/link/frame `i + 1`. So
//! [`Robot::frame`]`(q, i)` is the book's `⁰T_{i+1}`, [`Robot::u`]`(q, 4, 1)` is the
//! book's `U_52`, and `q[0]` is the book's `q_1`. The base frame (the book's frame 0)
//! is the identity and has no index here.
//!
//! # Conventions
//!
//! * Joint variable: revolute `θ_i = q_i + theta` (`d` constant); prismatic
//!   `d_i = q_i + d` (`theta` constant).
//! * [`Convention::Standard`] (Niku, Paul):
//!   `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)`.
//! * [`Convention::Modified`] (Craig): `A_i = Rotx(α) Transx(a) Rotz(θ_i) Transz(d_i)`,
//!   where the `a`, `alpha` stored in joint entry `i` are Craig's `a_{i−1}`, `α_{i−1}`;
//!   in a tree preceded by `Rotz(γ_i) Transz(b_i)`.
//! * [`Convention::Urdf`]: a joint is a fixed placement in its antecedent's link frame and
//!   a unit axis (URDF's `<origin>` and `<axis>`); link frame `i` is the joint frame moved.
//! * Inertial data: `com` is the centre of mass in link frame `i`; `inertia` holds the
//!   entries `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` of the inertia **tensor about the centre
//!   of mass** (off-diagonal entries are `−∫xy dm` etc., as in URDF). The book's
//!   pseudo-inertia uses the opposite sign for the products of inertia and moments
//!   about the frame origin; [`Robot::pseudo_inertia`] does the conversion.
//! * `gravity` is the gravity *acceleration* in the base frame (e.g. `[0, −9.81, 0]`),
//!   the book's `gᵀ = [gx, gy, gz, 0]` of eq. (6.45) without the trailing zero.
//!
//! # Example
//!
//! ```
//! use dynamics_reference::Robot;
//!
//! let json = r#"{
//!   "name": "pendulum", "convention": "standard", "gravity": [0.0, -9.81, 0.0],
//!   "joints": [{"type": "revolute", "theta": 0.0, "d": 0.0, "a": 1.0, "alpha": 0.0,
//!               "mass": 2.0, "com": [-0.5, 0.0, 0.0], "inertia": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]}]
//! }"#;
//! let robot = Robot::from_json(json).expect("valid description");
//! // A point mass of 2 kg at 0.5 m, horizontal: gravity torque m g l/2 cos(q).
//! let g = robot.gravity_torques(&[0.0]);
//! assert!((g[0] - 2.0 * 9.81 * 0.5).abs() < 1e-12);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod dynamics;
mod json;
mod kinematics;
mod pinocchio;
mod robot;
pub mod statics;

pub use kinematics::{
    axis_motion, axis_q_matrix, placement_matrix, q_matrix, rot_x, rot_z, trans_x, trans_z,
};
pub use pinocchio::PinocchioFrame;
pub use robot::{Convention, Joint, JointKind, Placement, Robot};

/// Re-export of the linear-algebra crate used in the public API.
pub use nalgebra;

/// The error measure of the reference data: `max|a − b| / max(1, max|b|)` over matching
/// entries, with `b` the reference; infinite if any value is not finite (`f64::max` would
/// silently drop a NaN).
///
/// # Panics
/// If the lengths differ.
#[must_use]
pub fn scaled_error(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len(), "length mismatch");
    if a.iter().chain(b).any(|x| !x.is_finite()) {
        return f64::INFINITY;
    }
    let diff = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0_f64, f64::max);
    let scale = b.iter().map(|y| y.abs()).fold(1.0_f64, f64::max);
    diff / scale
}
