//! The trait that `#[derive(Dynamics)]` implements.

use crate::Real;

/// Closed-form equations of motion of a serial robot with `N` joints,
/// `tau = M(q) qdd + C(q, qd) qd + g(q)` (Niku eq. 6.46).
///
/// Every method is straight-line code generated from the robot's D-H table: no loops, no
/// heap. Each is generic over the scalar, so one robot evaluates in `f32` or `f64`; the robot's
/// parameters (struct fields) are converted to that scalar on each call.
pub trait Dynamics<const N: usize> {
    /// Number of joints.
    const DOF: usize = N;

    /// Mass matrix `M(q)`: the book's D_ij (eq. 6.43) plus actuator inertia I_i(act) on the
    /// diagonal. Symmetric positive definite.
    fn mass_matrix<T: Real>(&self, q: &[T; N]) -> [[T; N]; N];

    /// Coriolis matrix `C(q, qd)` with `C_ij = Σ_k D_ijk qd_k`, where the book's D_ijk (eq. 6.44)
    /// are the Christoffel symbols of `M`. `Ṁ − 2C` is skew-symmetric.
    fn coriolis_matrix<T: Real>(&self, q: &[T; N], qd: &[T; N]) -> [[T; N]; N];

    /// Coriolis and centripetal torques `C(q, qd) qd = Σ_j Σ_k D_ijk qd_j qd_k`.
    fn coriolis_torques<T: Real>(&self, q: &[T; N], qd: &[T; N]) -> [T; N];

    /// Gravity torques `g(q)`: the book's D_i (eq. 6.45), plus joint spring torques
    /// `k_i (q_i − q0_i)`.
    fn gravity_torques<T: Real>(&self, q: &[T; N]) -> [T; N];

    /// Bias torques `C(q, qd) qd + g(q)` (Pinocchio's "non-linear effects").
    fn bias_torques<T: Real>(&self, q: &[T; N], qd: &[T; N]) -> [T; N];

    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (eq. 6.46), actuator inertia and
    /// springs included.
    fn inverse_dynamics<T: Real>(&self, q: &[T; N], qd: &[T; N], qdd: &[T; N]) -> [T; N];

    /// Kinetic energy `½ qdᵀ M(q) qd` (eq. 6.39), actuators included.
    fn kinetic_energy<T: Real>(&self, q: &[T; N], qd: &[T; N]) -> T;

    /// Potential energy `−Σ m_i gᵀ p_i + Σ ½ k_i (q_i − q0_i)²`, zero with every centre of mass
    /// at the base origin and every spring at rest.
    fn potential_energy<T: Real>(&self, q: &[T; N]) -> T;
}
