//! Examples of dynamics-runtime; see the `[[example]]` targets. The robot they share (the
//! identification examples, which run the command line, are `examples/identification/`):

use dynamics_runtime::Dynamics;

/// The PUMA 560 (Corke's Robotics Toolbox parameters) as a textbook D-H table, with a payload.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, 0, -9.81],
    derivatives = true,
    dh = [
        //  θ   d         a        α
        [   q,  0.67183,  0,       90 deg ],
        [   q,  0,        0.4318,  0      ],
        [   q,  0.15005,  0.0203, -90 deg ],
        [   q,  0.4318,   0,       90 deg ],
        [   q,  0,        0,      -90 deg ],
        [   q,  0,        0,       0      ],
    ],
    //   mass            centre of mass (frame i)        inertia about it [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]
    // Links 1 and 3 as published break the triangle inequality of principal moments
    // (0 + 0 < 0.35, 0.0125 + 0.066 < 0.086): `check_inertia = false` keeps them.
    link(mass = 0,                                       inertia = [0, 0.35, 0, 0, 0, 0], check_inertia = false),
    link(mass = 17.4,    com = [-0.3638, 0.006, 0.2275], inertia = [0.13, 0.524, 0.539, 0, 0, 0]),
    link(mass = 4.8,     com = [-0.0203, -0.0141, 0.07], inertia = [0.066, 0.086, 0.0125, 0, 0, 0], check_inertia = false),
    link(mass = 0.82,    com = [0, 0.019, 0],            inertia = [0.0018, 0.0013, 0.0018, 0, 0, 0]),
    link(mass = 0.34,                                    inertia = [0.0003, 0.0004, 0.0003, 0, 0, 0]),
    link(mass = 0.09 + payload, com = [0, 0, 0.032],     inertia = [0.00015, 0.00015, 0.00004, 0, 0, 0]),
)]
pub struct Puma560 {
    /// Extra mass carried at the last link's centre of mass, kg.
    pub payload: f64,
}

impl Puma560 {
    /// The examples' plant: `substeps` semi-implicit Euler steps of `h` seconds
    /// (`q̇ += h q̈`, then `q += h q̇`) under the torques `tau`, by the generated forward dynamics.
    pub fn simulate(
        &self,
        q: &mut [f64; 6],
        qd: &mut [f64; 6],
        tau: &[f64; 6],
        h: f64,
        substeps: usize,
    ) {
        for _ in 0..substeps {
            let qdd = self
                .forward_dynamics(q, qd, tau)
                .expect("M(q) is positive definite");
            for i in 0..6 {
                qd[i] += h * qdd[i];
                q[i] += h * qd[i];
            }
        }
    }
}
