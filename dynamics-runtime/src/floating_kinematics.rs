//! The kinematic outputs of a robot on a free-flying base, which `#[derive(Dynamics)]`
//! implements beside `FloatingDynamics` for `base = floating` (see `docs/floating-base.md`).

use crate::{Pose, Real};

/// The centre of mass, the centroidal momentum and the named frames' kinematics of a tree on
/// a free-flying base, in Pinocchio's conventions (its free flyer; `q`, `v` as
/// [`crate::FloatingDynamics`]'s: `Q = n + 7`, `V = n + 6`). `F` frames: the links
/// `tips = [..]` names, in their order, else every leaf link of the URDF below a moving joint
/// (a quadruped's feet), in the file's order; named by the derive's `Robot::FRAME_NAMES` and an
/// index per frame (`Robot::FRAME_FL_FOOT`). Naming frames keeps every branch of the robot.
///
/// Everything is in the world frame unless said otherwise. The base position enters only the
/// centre of mass and the frames' positions.
pub trait FloatingKinematics<const Q: usize, const V: usize, const F: usize> {
    /// Number of frames.
    const FRAME_COUNT: usize = F;

    /// The centre of mass in the world (Pinocchio's `centerOfMass`).
    fn center_of_mass<T: Real>(&self, q: &[T; Q]) -> [T; 3];

    /// The centre of mass's Jacobian, `ċ = J v`, in world axes (`jacobianCenterOfMass`).
    fn center_of_mass_jacobian<T: Real>(&self, q: &[T; Q]) -> [[T; V]; 3];

    /// The centroidal momentum matrix `A_G` (`computeCentroidalMap`): `A_G v` is the robot's
    /// momentum, linear then angular, about the centre of mass in world axes.
    fn centroidal_momentum_matrix<T: Real>(&self, q: &[T; Q]) -> [[T; V]; 6];

    /// `Ȧ_G v` (`computeCentroidalMapTimeVariation`'s `dAg` times `v`): the rate of the
    /// centroidal momentum at `a = 0`, so that `ḣ_G = A_G a + Ȧ_G v`.
    fn centroidal_momentum_bias<T: Real>(&self, q: &[T; Q], v: &[T; V]) -> [T; 6];

    /// Each frame's pose in the world (Pinocchio's `oMf`).
    fn frame_poses<T: Real>(&self, q: &[T; Q]) -> [Pose<T>; F];

    /// Each frame's Jacobian in LOCAL_WORLD_ALIGNED (`getFrameJacobian`): rows
    /// `[v_x, v_y, v_z, ω_x, ω_y, ω_z]`, the velocity of the frame's origin and its angular
    /// velocity, in world axes.
    fn frame_jacobians_world_aligned<T: Real>(&self, q: &[T; Q]) -> [[[T; V]; 6]; F];

    /// Each frame's Jacobian in LOCAL: the same in the frame's own axes.
    fn frame_jacobians_local<T: Real>(&self, q: &[T; Q]) -> [[[T; V]; 6]; F];

    /// Each frame's `J̇ v` in world axes: its classical acceleration at `a = 0`
    /// (`getFrameClassicalAcceleration` in LOCAL_WORLD_ALIGNED): the acceleration of its
    /// origin in the world, then its angular acceleration; `J a + J̇ v` is the frame's
    /// acceleration, as legged MPC writes a foot's contact constraint.
    fn frame_acceleration_biases_world_aligned<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
    ) -> [[T; 6]; F];

    /// Each frame's `J̇ v` in its own axes (`getFrameClassicalAcceleration` in LOCAL).
    fn frame_acceleration_biases_local<T: Real>(&self, q: &[T; Q], v: &[T; V]) -> [[T; 6]; F];
}
