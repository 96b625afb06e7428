//! The trait of a robot on a free-flying base, which `#[derive(Dynamics)]` implements for
//! `base = floating` (see `docs/floating-base.md`).

use crate::Real;

/// Closed-form dynamics of a kinematic tree on a free-flying base, Pinocchio's free flyer:
/// `τ = M(q) a + h(q, v)`.
///
/// The configuration `q` has `Q = NQ = n + 7` entries,
/// `[x, y, z, qx, qy, qz, qw, q_1 … q_n]`: the base origin in the world, the base orientation
/// as a unit quaternion, then the joints. The velocity `v` and acceleration `a` have
/// `V = NV = n + 6`, `[v_x, v_y, v_z, ω_x, ω_y, ω_z, q̇_1 …]`: the base origin's velocity and
/// the base's angular velocity, both in the base frame, then
/// the joint rates. The first six rows of a generalized force are the wrench on the base,
/// `[f_x, f_y, f_z, m_x, m_y, m_z]` in the base frame, its moment about the base origin.
///
/// The quaternion is read as given: its rotation matrix is the polynomial of its components,
/// a rotation only if it is unit (as in Pinocchio). Only gravity reads it; nothing reads the
/// base position.
pub trait FloatingDynamics<const Q: usize, const V: usize> {
    /// The configuration's length, `n + 7`.
    const NQ: usize = Q;
    /// The velocity's length, `n + 6`.
    const NV: usize = V;

    /// The mass matrix `M(q)`, base rows and columns first (Pinocchio's `crba`, symmetric).
    fn mass_matrix<T: Real>(&self, q: &[T; Q]) -> [[T; V]; V];

    /// The bias `h(q, v) = C(q, v) v + g(q)` (Pinocchio's `nonLinearEffects`).
    fn bias_forces<T: Real>(&self, q: &[T; Q], v: &[T; V]) -> [T; V];

    /// Inverse dynamics `τ = M(q) a + h(q, v)` (Pinocchio's `rnea`): the base's six rows are
    /// the wrench the base needs (from contacts), the others the joint torques.
    fn inverse_dynamics<T: Real>(&self, q: &[T; Q], v: &[T; V], a: &[T; V]) -> [T; V];

    /// The generalized gravity `g(q)` (Pinocchio's `computeGeneralizedGravity`).
    fn generalized_gravity<T: Real>(&self, q: &[T; Q]) -> [T; V];
}
