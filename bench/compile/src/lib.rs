//! Two 7-joint robots whose 70 inertial parameters are all struct fields, derived with every
//! family (derivatives, regressor, base parameters), the methods of the dynamics, forward
//! dynamics, derivatives, regressor and base regressor instantiated in `f64` and `f32`: the
//! compile-time case of issues 3, 18 and 42, timed by `bench/compile-time`.
use dynamics_runtime::{
    Dynamics, DynamicsBaseParameters, DynamicsDerivatives, DynamicsRegressor, Real,
};

/// KUKA iiwa 14 kinematics, parameters as fields.
#[derive(Dynamics)]
#[dynamics(
    file = "../robots/iiwa14_fields.toml",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct A {
    pub m1: f64,
    pub cx1: f64,
    pub cy1: f64,
    pub cz1: f64,
    pub ixx1: f64,
    pub iyy1: f64,
    pub izz1: f64,
    pub ixy1: f64,
    pub ixz1: f64,
    pub iyz1: f64,
    pub m2: f64,
    pub cx2: f64,
    pub cy2: f64,
    pub cz2: f64,
    pub ixx2: f64,
    pub iyy2: f64,
    pub izz2: f64,
    pub ixy2: f64,
    pub ixz2: f64,
    pub iyz2: f64,
    pub m3: f64,
    pub cx3: f64,
    pub cy3: f64,
    pub cz3: f64,
    pub ixx3: f64,
    pub iyy3: f64,
    pub izz3: f64,
    pub ixy3: f64,
    pub ixz3: f64,
    pub iyz3: f64,
    pub m4: f64,
    pub cx4: f64,
    pub cy4: f64,
    pub cz4: f64,
    pub ixx4: f64,
    pub iyy4: f64,
    pub izz4: f64,
    pub ixy4: f64,
    pub ixz4: f64,
    pub iyz4: f64,
    pub m5: f64,
    pub cx5: f64,
    pub cy5: f64,
    pub cz5: f64,
    pub ixx5: f64,
    pub iyy5: f64,
    pub izz5: f64,
    pub ixy5: f64,
    pub ixz5: f64,
    pub iyz5: f64,
    pub m6: f64,
    pub cx6: f64,
    pub cy6: f64,
    pub cz6: f64,
    pub ixx6: f64,
    pub iyy6: f64,
    pub izz6: f64,
    pub ixy6: f64,
    pub ixz6: f64,
    pub iyz6: f64,
    pub m7: f64,
    pub cx7: f64,
    pub cy7: f64,
    pub cz7: f64,
    pub ixx7: f64,
    pub iyy7: f64,
    pub izz7: f64,
    pub ixy7: f64,
    pub ixz7: f64,
    pub iyz7: f64,
}

/// The same arm with another link length.
#[derive(Dynamics)]
#[dynamics(
    file = "iiwa14_fields_b.toml",
    derivatives = true,
    regressor = true,
    base_parameters = true
)]
pub struct B {
    pub m1: f64,
    pub cx1: f64,
    pub cy1: f64,
    pub cz1: f64,
    pub ixx1: f64,
    pub iyy1: f64,
    pub izz1: f64,
    pub ixy1: f64,
    pub ixz1: f64,
    pub iyz1: f64,
    pub m2: f64,
    pub cx2: f64,
    pub cy2: f64,
    pub cz2: f64,
    pub ixx2: f64,
    pub iyy2: f64,
    pub izz2: f64,
    pub ixy2: f64,
    pub ixz2: f64,
    pub iyz2: f64,
    pub m3: f64,
    pub cx3: f64,
    pub cy3: f64,
    pub cz3: f64,
    pub ixx3: f64,
    pub iyy3: f64,
    pub izz3: f64,
    pub ixy3: f64,
    pub ixz3: f64,
    pub iyz3: f64,
    pub m4: f64,
    pub cx4: f64,
    pub cy4: f64,
    pub cz4: f64,
    pub ixx4: f64,
    pub iyy4: f64,
    pub izz4: f64,
    pub ixy4: f64,
    pub ixz4: f64,
    pub iyz4: f64,
    pub m5: f64,
    pub cx5: f64,
    pub cy5: f64,
    pub cz5: f64,
    pub ixx5: f64,
    pub iyy5: f64,
    pub izz5: f64,
    pub ixy5: f64,
    pub ixz5: f64,
    pub iyz5: f64,
    pub m6: f64,
    pub cx6: f64,
    pub cy6: f64,
    pub cz6: f64,
    pub ixx6: f64,
    pub iyy6: f64,
    pub izz6: f64,
    pub ixy6: f64,
    pub ixz6: f64,
    pub iyz6: f64,
    pub m7: f64,
    pub cx7: f64,
    pub cy7: f64,
    pub cz7: f64,
    pub ixx7: f64,
    pub iyy7: f64,
    pub izz7: f64,
    pub ixy7: f64,
    pub ixz7: f64,
    pub iyz7: f64,
}

/// Every method of `r` at one state, summed so that none is optimized away.
fn all<R: DynamicsDerivatives<7>, T: Real>(r: &R, q: &[T; 7], qd: &[T; 7], qdd: &[T; 7]) -> T {
    let tau = r.inverse_dynamics(q, qd, qdd);
    let m = r.mass_matrix(q);
    let c = r.coriolis_matrix(q, qd);
    let g = r.gravity_torques(q);
    let h = r.bias_torques(q, qd);
    let cqd = r.coriolis_torques(q, qd);
    let mut sum = r.kinetic_energy(q, qd) + r.potential_energy(q);
    for i in 0..7 {
        sum += tau[i] + m[i][i] + c[i][0] + g[i] + h[i] + cqd[i];
    }
    let forward = (r.forward_dynamics(q, qd, &tau), r.mass_matrix_inverse(q));
    if let (Ok(qdd), Ok(inverse)) = forward {
        for i in 0..7 {
            sum += qdd[i] + inverse[i][i];
        }
    }
    let inverse = r.inverse_dynamics_derivatives(q, qd, qdd);
    for i in 0..7 {
        sum += inverse.dtau_dq[i][0] + inverse.dtau_dqd[i][0];
    }
    if let Ok(forward) = r.forward_dynamics_derivatives(q, qd, &tau) {
        for i in 0..7 {
            sum += forward.dqdd_dq[i][0] + forward.dqdd_dqd[i][0] + forward.dqdd_dtau[i][0];
        }
    }
    sum
}

/// The regressor's and the base regressor's elements of `r` at one state, summed.
fn identification<R, T: Real, const P: usize>(r: &R, q: &[T; 7], qd: &[T; 7], qdd: &[T; 7]) -> T
where
    R: DynamicsRegressor<7> + DynamicsBaseParameters<7, P>,
{
    let y = r.regressor(q, qd, qdd);
    let yb = r.base_regressor(q, qd, qdd);
    let mut sum = T::ZERO;
    for i in 0..7 {
        sum += y[i][i][0] + yb[i][0];
    }
    sum
}

/// Both robots in `f64`.
pub fn f64s(a: &A, b: &B, q: &[f64; 7], qd: &[f64; 7], qdd: &[f64; 7]) -> f64 {
    all(a, q, qd, qdd)
        + all(b, q, qd, qdd)
        + identification(a, q, qd, qdd)
        + identification(b, q, qd, qdd)
}

/// Both robots in `f32`.
pub fn f32s(a: &A, b: &B, q: &[f32; 7], qd: &[f32; 7], qdd: &[f32; 7]) -> f32 {
    all(a, q, qd, qdd)
        + all(b, q, qd, qdd)
        + identification(a, q, qd, qdd)
        + identification(b, q, qd, qdd)
}
