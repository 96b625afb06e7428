//! A `#![no_std]` crate that derives robots and calls every method, in `f32` and `f64`.
//! It builds only if generated code and the runtime (with `libm`) need nothing from std.
#![no_std]

use dynamics_runtime::{Dynamics, DynamicsBaseParameters, DynamicsDerivatives, DynamicsRegressor};

/// A 6-joint robot with prismatic joints and products of inertia, from a description file.
#[derive(Dynamics)]
#[dynamics(
    file = "../data/reference/robots/random5.json",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct Random5;

/// A planar arm whose lengths, masses, spring and gravity are fields.
#[derive(Dynamics)]
#[dynamics(
    derivatives = true,
    regressor = true,
    gravity = [0, -g, 0],
    dh = [
        //  θ          d   a    α
        [   q,         0,  l1,  0 ],
        [   q + 0.25,  0,  l2,  0 ],
    ],
    link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0, m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0]),
    link(mass = m2, com = [-l2 / 2, 0, 0], inertia = [0, m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0],
         actuator_inertia = 0.02, spring = (k, 0.1)),
)]
pub struct TwoLink {
    /// Link lengths, m.
    pub l1: f32,
    /// Link lengths, m.
    pub l2: f32,
    /// Masses, kg.
    pub m1: f32,
    /// Masses, kg.
    pub m2: f32,
    /// Spring stiffness, N m / rad.
    pub k: f32,
    /// Gravity, m/s².
    pub g: f32,
}

/// Every method, in single precision, summed so that nothing is optimized away.
#[must_use]
pub fn evaluate_f32<R: DynamicsDerivatives<N> + DynamicsRegressor<N>, const N: usize>(
    robot: &R,
    q: &[f32; N],
    qd: &[f32; N],
    qdd: &[f32; N],
) -> f32 {
    let m = robot.mass_matrix(q);
    let c = robot.coriolis_matrix(q, qd);
    let cqd = robot.coriolis_torques(q, qd);
    let g = robot.gravity_torques(q);
    let h = robot.bias_torques(q, qd);
    let tau = robot.inverse_dynamics(q, qd, qdd);
    // The error (a singular M) as NaN.
    let qdd_back = robot
        .forward_dynamics(q, qd, &tau)
        .map_or(f32::NAN, |a| a[0]);
    let inverse = robot.mass_matrix_inverse(q).map_or(f32::NAN, |m| m[0][0]);
    let derivatives = robot.inverse_dynamics_derivatives(q, qd, qdd);
    let forward = robot
        .forward_dynamics_derivatives(q, qd, &tau)
        .map_or(f32::NAN, |d| d.dqdd_dq[0][0] + d.dqdd_dqd[0][0]);
    let mut written = [[[0.0; 10]; N]; N];
    robot.regressor_into(q, qd, qdd, &mut written);
    let regressor = robot.regressor(q, qd, qdd)[0][N - 1][9] + written[0][N - 1][9];
    let parameters = robot.standard_parameters::<f32>()[N - 1][0];
    let joints = robot.joint_regressor(qd, qdd)[0][2] + robot.joint_parameters::<f32>()[0][0];
    m[0][0]
        + c[N - 1][0]
        + cqd[0]
        + g[0]
        + h[0]
        + tau[N - 1]
        + robot.kinetic_energy(q, qd)
        + robot.potential_energy(q)
        + qdd_back
        + inverse
        + derivatives.dtau_dq[0][N - 1]
        + derivatives.dtau_dqd[N - 1][0]
        + forward
        + regressor
        + parameters
        + joints
}

/// `Y_B π_B`'s first row, in single precision.
#[must_use]
pub fn base_torque_f32<R: DynamicsBaseParameters<N, B>, const N: usize, const B: usize>(
    robot: &R,
    q: &[f32; N],
    qd: &[f32; N],
    qdd: &[f32; N],
) -> f32 {
    let mut y = [[0.0; B]; N];
    robot.base_regressor_into(q, qd, qdd, &mut y);
    let pi = robot.base_parameters::<f32>();
    y[0].iter().zip(&pi).map(|(a, b)| a * b).sum::<f32>() + robot.base_regressor(q, qd, qdd)[0][0]
}

/// Random5's, as the generic function runs it.
#[must_use]
pub fn base_torque_random5(q: &[f32; 6]) -> f32 {
    base_torque_f32(&Random5, q, q, q)
}

/// Inverse dynamics of both robots in double precision, and the derivatives of one.
#[must_use]
pub fn torques_f64(arm: &TwoLink, q: &[f64; 6]) -> ([f64; 6], [f64; 2], [[f64; 6]; 6]) {
    let zero = [0.0; 6];
    (
        Random5.inverse_dynamics(q, &zero, &zero),
        arm.inverse_dynamics(&[q[0], q[1]], &[0.0; 2], &[0.0; 2]),
        Random5
            .inverse_dynamics_derivatives(q, &zero, &zero)
            .dtau_dq,
    )
}

/// Random5's forward dynamics (at its inverse dynamics' torques) on four states at once in
/// `f64` lanes (AVX2 registers where the build has AVX2, else arrays), the arm's inverse
/// dynamics on eight in `f32` lanes: the lane types need nothing from std either.
#[must_use]
pub fn accelerations_lanes(arm: &TwoLink, q: &[[f64; 6]; 4]) -> ([[f64; 6]; 4], [[f32; 2]; 8]) {
    use dynamics_runtime::lanes::{gather, SplitLanes};
    use dynamics_runtime::{F32x8, F64x4};
    let q: [F64x4; 6] = gather(q);
    let zero = [F64x4::splat(0.0); 6];
    let qf = [F32x8::splat(0.5), F32x8::splat(-0.25)];
    let zf = [F32x8::splat(0.0); 2];
    let tau = Random5.inverse_dynamics(&q, &zero, &zero);
    // `Err` where at least one lane's mass matrix is not positive definite.
    let qdd = Random5.forward_dynamics(&q, &zero, &tau).unwrap_or(zero);
    (
        qdd.split_lanes(),
        arm.inverse_dynamics(&qf, &zf, &zf).split_lanes(),
    )
}
