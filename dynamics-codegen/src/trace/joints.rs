//! What each joint adds outside the rigid-body algorithms: its variables `q`, `q̇`, `q̈`, the
//! actuator inertia I_i(act) of eq. 6.39 (on `M_ii`, `I q̈_i` in `τ_i`, `½ I q̇_i²` in the
//! kinetic energy) and an optional spring (`k (q_i − rest)` in `g_i`, `½ k (q_i − rest)²` in
//! the potential energy).

use super::expr::Expr;
use super::tracer::Tracer;
use crate::algo::RobotScalars;
use crate::model::Robot;
use crate::symbolic::Var;

/// Per joint, its variables, actuator inertia and spring `(k, rest)`, traced.
pub(super) struct JointTerms<'g> {
    pub zero: Expr<'g>,
    pub q: Vec<Expr<'g>>,
    pub qd: Vec<Expr<'g>>,
    pub qdd: Vec<Expr<'g>>,
    pub actuator: Vec<Expr<'g>>,
    pub springs: Vec<Option<(Expr<'g>, Expr<'g>)>>,
}

impl<'g> JointTerms<'g> {
    /// The terms of `robot`'s joints.
    pub(super) fn new(t: &Tracer<'g>, robot: &Robot, zero: Expr<'g>) -> JointTerms<'g> {
        let n = robot.dof();
        JointTerms {
            zero,
            q: t.joint_vars(n, Var::Q),
            qd: t.joint_vars(n, Var::Qd),
            qdd: t.joint_vars(n, Var::Qdd),
            actuator: robot
                .joints
                .iter()
                .map(|j| t.value(&j.link.actuator_inertia))
                .collect(),
            springs: robot
                .joints
                .iter()
                .map(|j| {
                    j.link
                        .spring
                        .as_ref()
                        .map(|s| (t.value(&s.stiffness), t.value(&s.rest)))
                })
                .collect(),
        }
    }

    /// Zero per joint.
    pub(super) fn zeros(&self) -> Vec<Expr<'g>> {
        vec![self.zero; self.q.len()]
    }

    /// The torque of joint `i`'s spring, `k (q_i − rest)`.
    pub(super) fn spring_torque(&self, i: usize) -> Expr<'g> {
        self.springs[i].map_or(self.zero, |(k, rest)| k * (self.q[i] - rest))
    }

    /// `torques` with the springs' torques added.
    pub(super) fn with_springs(&self, torques: Vec<Expr<'g>>) -> Vec<Expr<'g>> {
        torques
            .into_iter()
            .enumerate()
            .map(|(i, x)| x + self.spring_torque(i))
            .collect()
    }

    /// `M` with the actuator inertia added on its diagonal.
    pub(super) fn with_actuator_inertia(&self, mut mass: Vec<Vec<Expr<'g>>>) -> Vec<Vec<Expr<'g>>> {
        for (i, row) in mass.iter_mut().enumerate() {
            row[i] = row[i] + self.actuator[i];
        }
        mass
    }
}
