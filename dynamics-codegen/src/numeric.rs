//! The algorithms of [`crate::algo`] run on `f64`: a plain numeric recursive Newton-Euler and
//! composite-rigid-body implementation of a [`Robot`], with loops over joints at run time.
//! It is what the generated code is measured against, and a second numeric implementation
//! beside the book's method of `dynamics-reference`.

use crate::algo::{self, Chain, RobotScalars, V3};
use crate::model::{Robot, Value};

/// A robot evaluated numerically.
#[derive(Clone, Debug)]
pub struct Numeric {
    robot: Robot,
    values: Vec<f64>,
    fields: Vec<String>,
}

/// A value of the robot named no field that `Numeric::new` was given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MissingField(pub String);

impl Numeric {
    /// The robot, with its fields' values given by name.
    ///
    /// # Errors
    /// The first field the robot names that `fields` lacks.
    pub fn new(robot: &Robot, fields: &[(&str, f64)]) -> Result<Numeric, MissingField> {
        let names = robot.fields();
        let values = names
            .iter()
            .map(|n| {
                fields
                    .iter()
                    .find(|(f, _)| f == n)
                    .map(|(_, v)| *v)
                    .ok_or_else(|| MissingField(n.clone()))
            })
            .collect::<Result<Vec<f64>, _>>()?;
        Ok(Numeric {
            robot: robot.clone(),
            values,
            fields: names,
        })
    }

    fn value(&self, v: &Value) -> f64 {
        v.eval(&|f| {
            self.fields
                .iter()
                .position(|x| x == f)
                .map(|k| self.values[k])
        })
        .unwrap_or(f64::NAN)
    }

    /// The chain at position `q`, one entry per joint.
    #[must_use]
    pub fn chain(&self, q: &[f64]) -> Chain<f64> {
        AtPosition { numeric: self, q }.chain(&self.robot)
    }

    fn gravity(&self) -> V3<f64> {
        AtPosition {
            numeric: self,
            q: &[],
        }
        .gravity(&self.robot)
    }

    fn springs(&self, q: &[f64]) -> Vec<f64> {
        self.robot
            .joints
            .iter()
            .zip(q)
            .map(|(j, qi)| {
                j.link.spring.as_ref().map_or(0.0, |s| {
                    self.value(&s.stiffness) * (qi - self.value(&s.rest))
                })
            })
            .collect()
    }

    /// `tau = M(q) qdd + C(q, qd) qd + g(q)` by recursive Newton-Euler, with actuator inertia,
    /// springs and friction.
    #[must_use]
    pub fn inverse_dynamics(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
        let tau = algo::rnea(&self.chain(q), qd, qdd, self.gravity());
        let springs = self.springs(q);
        let friction = self.friction_torques(qd);
        tau.iter()
            .zip(&self.robot.joints)
            .enumerate()
            .map(|(i, (t, j))| {
                t + self.value(&j.link.actuator_inertia) * qdd[i] + springs[i] + friction[i]
            })
            .collect()
    }

    /// Joint friction `f_v qd + f_c sign(qd) + f_0` (`f_c tanh(qd / ε)` smoothed), `sign(0) = 0`.
    #[must_use]
    pub fn friction_torques(&self, qd: &[f64]) -> Vec<f64> {
        let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
        self.robot
            .joints
            .iter()
            .zip(qd)
            .map(|(j, &v)| {
                j.link.friction.as_ref().map_or(0.0, |f| {
                    let direction = f
                        .smoothing
                        .as_ref()
                        .map_or_else(|| sign(v), |eps| (v / self.value(eps)).tanh());
                    self.value(&f.viscous) * v
                        + self.value(&f.coulomb) * direction
                        + self.value(&f.offset)
                })
            })
            .collect()
    }

    /// Kinetic energy `½ q̇ᵀ M q̇` (links and actuators) and potential energy (gravity, zero
    /// with every centre of mass at the base origin, and springs `½ k (q − q_rest)²`).
    #[must_use]
    pub fn energies(&self, q: &[f64], qd: &[f64]) -> (f64, f64) {
        let chain = self.chain(q);
        let mut kinetic = algo::kinetic_energy(&chain, qd, 0.0);
        let mut potential = algo::potential_energy(&chain, self.gravity());
        for ((j, qi), v) in self.robot.joints.iter().zip(q).zip(qd) {
            kinetic += 0.5 * self.value(&j.link.actuator_inertia) * v * v;
            if let Some(s) = &j.link.spring {
                let stretch = qi - self.value(&s.rest);
                potential += 0.5 * self.value(&s.stiffness) * stretch * stretch;
            }
        }
        (kinetic, potential)
    }

    /// `M(q)` by the composite rigid body algorithm, with actuator inertia.
    #[must_use]
    pub fn mass_matrix(&self, q: &[f64]) -> Vec<Vec<f64>> {
        let mut m = algo::crba(&self.chain(q));
        for (i, j) in self.robot.joints.iter().enumerate() {
            m[i][i] += self.value(&j.link.actuator_inertia);
        }
        m
    }

    /// `g(q)` with springs.
    #[must_use]
    pub fn gravity_torques(&self, q: &[f64]) -> Vec<f64> {
        let zeros = vec![0.0; q.len()];
        let g = algo::rnea(&self.chain(q), &zeros, &zeros, self.gravity());
        g.iter().zip(self.springs(q)).map(|(a, b)| a + b).collect()
    }

    /// `q̈ = M⁻¹ (τ − C q̇ − g − τ_f)`, through the LDLᵀ of `M(q)`.
    ///
    /// # Errors
    /// The first pivot of the LDLᵀ that is not positive (`M(q)` is then not positive definite).
    pub fn forward_dynamics(
        &self,
        q: &[f64],
        qd: &[f64],
        tau: &[f64],
    ) -> Result<Vec<f64>, NotPositiveDefinite> {
        let zeros = vec![0.0; q.len()];
        let bias = self.inverse_dynamics(q, qd, &zeros);
        let rhs: Vec<f64> = tau.iter().zip(&bias).map(|(t, b)| t - b).collect();
        let factors = algo::Ldlt::new(&self.mass_matrix(q));
        // `!(d > 0)`: a NaN pivot is not positive either.
        match factors
            .pivots
            .iter()
            .position(|d| d.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater))
        {
            Some(k) => Err(NotPositiveDefinite {
                pivot: k,
                value: factors.pivots[k],
            }),
            None => Ok(factors.solve(&rhs)),
        }
    }
}

/// `M(q)` is not positive definite: pivot `pivot` (0-based) of its LDLᵀ is `value`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NotPositiveDefinite {
    /// The pivot's index, 0-based.
    pub pivot: usize,
    /// Its value: zero, negative or NaN.
    pub value: f64,
}

/// The robot's values evaluated, at joint position `q`.
struct AtPosition<'a> {
    numeric: &'a Numeric,
    q: &'a [f64],
}

impl RobotScalars for AtPosition<'_> {
    type Scalar = f64;

    fn value(&self, v: &Value) -> f64 {
        self.numeric.value(v)
    }

    fn sin_cos(&self, v: &Value) -> (f64, f64) {
        let x = self.value(v);
        (x.sin(), x.cos())
    }

    fn joint_variable(&self, joint: usize) -> f64 {
        self.q[joint]
    }

    fn joint_sin_cos(&mut self, joint: usize, offset: &Value) -> (f64, f64) {
        let theta = self.q[joint] + self.value(offset);
        (theta.sin(), theta.cos())
    }
}
