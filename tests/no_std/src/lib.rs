//! A `#![no_std]` crate that derives a robot and calls every method, in `f32` and `f64`.
//! It builds only if generated code and the runtime (with `libm`) need nothing from std.
#![no_std]

use dynamics_runtime::Dynamics;

/// The PUMA 560 of the reference data, with a payload mass as a field.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    dh = [
        //  θ   d         a        α
        [   q,  0.67183,  0,       90 deg ],
        [   q,  0,        0.4318,  0      ],
        [   q,  0.15005,  0.0203, -90 deg ],
        [   q,  0.4318,   0,       90 deg ],
        [   q,  0,        0,      -90 deg ],
        [   q,  0,        0,       0      ],
    ],
    link(mass = 0, inertia = [0, 0.35, 0, 0, 0, 0]),
    link(mass = 17.4, com = [-0.3638, 0.006, 0.2275], inertia = [0.13, 0.524, 0.539, 0, 0, 0]),
    link(mass = 4.8, com = [-0.0203, -0.0141, 0.07], inertia = [0.066, 0.086, 0.0125, 0, 0, 0]),
    link(mass = 0.82, com = [0, 0.019, 0], inertia = [0.0018, 0.0013, 0.0018, 0, 0, 0]),
    link(mass = 0.34, inertia = [0.0003, 0.0004, 0.0003, 0, 0, 0]),
    link(mass = 0.09 + payload, com = [0, 0, 0.032], inertia = [0.00015, 0.00015, 0.00004, 0, 0, 0]),
)]
pub struct Puma560 {
    /// Payload at the last link's centre of mass, kg.
    pub payload: f32,
}

/// Every method, in single precision.
#[must_use]
pub fn evaluate_f32(robot: &Puma560, q: &[f32; 6], qd: &[f32; 6], qdd: &[f32; 6]) -> f32 {
    let m = robot.mass_matrix(q);
    let c = robot.coriolis_matrix(q, qd);
    let cqd = robot.coriolis_torques(q, qd);
    let g = robot.gravity_torques(q);
    let h = robot.bias_torques(q, qd);
    let tau = robot.inverse_dynamics(q, qd, qdd);
    m[0][0]
        + c[1][2]
        + cqd[0]
        + g[1]
        + h[2]
        + tau[3]
        + robot.kinetic_energy(q, qd)
        + robot.potential_energy(q)
}

/// Inverse dynamics in double precision.
#[must_use]
pub fn torques_f64(robot: &Puma560, q: &[f64; 6], qd: &[f64; 6], qdd: &[f64; 6]) -> [f64; 6] {
    robot.inverse_dynamics(q, qd, qdd)
}
