//! The terms of the inverse dynamics apart, per joint, four samples at a time:
//! `τ = M_links q̈ + C q̇ + g + I_a q̈ + τ_f`, from the robot's graph through a [`JointTape`] of
//! τ, `C q̇` (`coriolis_torques`), g with the springs (`gravity_torques`) and the friction, the
//! actuators' `I_a q̈` from the description, and the links' inertial term the rest of τ.

use crate::joint_tape::{gather, JointTape, Work};
use crate::lanes::{Four, LANES};
use dynamics_codegen::model::Robot;
use dynamics_codegen::pipeline::TapeScalar;
use dynamics_codegen::Equations;

/// The terms of the inverse dynamics apart, per joint.
#[derive(Clone, Debug, PartialEq)]
pub struct Terms {
    /// `M_links(q) q̈`.
    pub inertial: Vec<f64>,
    /// `C(q, q̇) q̇`.
    pub coriolis: Vec<f64>,
    /// `g(q)` with springs.
    pub gravity: Vec<f64>,
    /// The actuators' inertia, `I_a q̈`.
    pub actuator: Vec<f64>,
    /// Joint friction.
    pub friction: Vec<f64>,
}

/// One robot's terms of τ, ready to evaluate.
pub struct TermsTape {
    tape: JointTape,
    /// `I_a` per joint.
    actuator_inertia: Vec<f64>,
    work: Work,
    out: Vec<Four>,
}

/// One sample's joint values.
pub struct At<'a> {
    pub q: &'a [f64],
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
}

impl TermsTape {
    /// The terms of `robot`, whose traced equations are `eq` and fields' values `fields` (in
    /// the order of `eq.fields`).
    ///
    /// # Errors
    /// A field without a value.
    pub fn new(robot: &Robot, eq: &Equations, fields: &[f64]) -> Result<TermsTape, String> {
        let outputs: Vec<_> = [&eq.tau, &eq.coriolis_torques, &eq.gravity, &eq.friction]
            .into_iter()
            .flatten()
            .copied()
            .collect();
        let tape = JointTape::new(&eq.graph, &outputs, &eq.angle_offsets, fields, None)?;
        let field = |name: &str| {
            let k = eq.fields.iter().position(|f| f == name)?;
            fields.get(k).copied()
        };
        let actuator_inertia = robot
            .joints
            .iter()
            .map(|j| j.link.actuator_inertia.eval(&field))
            .collect::<Option<Vec<f64>>>()
            .ok_or("an actuator inertia without a value")?;
        Ok(TermsTape {
            out: vec![Four::splat(0.0); outputs.len()],
            tape,
            actuator_inertia,
            work: Work::default(),
        })
    }

    /// The terms at up to [`LANES`] samples, in their order.
    ///
    /// # Panics
    /// With no sample or more than [`LANES`].
    pub fn terms(&mut self, samples: &[At<'_>]) -> Vec<Terms> {
        assert!((1..=LANES).contains(&samples.len()), "1 to {LANES} samples");
        let n = self.actuator_inertia.len();
        let lanes =
            |values: Vec<&[f64]>| -> Vec<Four> { (0..n).map(|j| gather(&values, j)).collect() };
        let q = lanes(samples.iter().map(|s| s.q).collect());
        let qd = lanes(samples.iter().map(|s| s.qd).collect());
        let qdd = lanes(samples.iter().map(|s| s.qdd).collect());
        self.tape.eval(&q, &qd, &qdd, &mut self.work, &mut self.out);
        let values: Vec<[f64; LANES]> = self.out.iter().map(|x| x.lanes()).collect();
        samples
            .iter()
            .enumerate()
            .map(|(l, s)| {
                let part =
                    |k: usize| -> Vec<f64> { (0..n).map(|i| values[k * n + i][l]).collect() };
                let (tau, coriolis, gravity, friction) = (part(0), part(1), part(2), part(3));
                let actuator: Vec<f64> = (0..n)
                    .map(|i| self.actuator_inertia[i] * s.qdd[i])
                    .collect();
                let inertial = (0..n)
                    .map(|i| tau[i] - coriolis[i] - gravity[i] - actuator[i] - friction[i])
                    .collect();
                Terms {
                    inertial,
                    coriolis,
                    gravity,
                    actuator,
                    friction,
                }
            })
            .collect()
    }
}
