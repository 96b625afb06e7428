//! What embedded use looks like: a 1 kHz joint controller for the PUMA 560 in `f32`, with no
//! heap (arrays on the stack only), computing gravity compensation plus a PD term,
//! `τ = g(q) + K_p (q* − q) − K_d q̇`, with the gains placed from the diagonal of M(q*)
//! (`K_p = M_ii ω²`, `K_d = 2 M_ii ω`: each joint a critically damped ω = 20 rad/s system).
//!
//! The robot it drives is simulated in `f64` by the generated `forward_dynamics` (semi-implicit
//! Euler, ten substeps per control period). Gravity compensation removes the steady-state error
//! a PD term alone would leave.
//!
//! Run with `cargo run --release -p dynamics-examples --example realtime_loop`.

use dynamics_examples::Puma560;
use dynamics_runtime::Dynamics;

const PERIOD: f32 = 0.001;
const OMEGA: f32 = 20.0;
const SUBSTEPS: usize = 10;

/// The controller's state: its gains and target, nothing allocated.
struct Controller {
    robot: Puma560,
    target: [f32; 6],
    kp: [f32; 6],
    kd: [f32; 6],
}

impl Controller {
    fn new(robot: Puma560, target: [f32; 6]) -> Controller {
        let m = robot.mass_matrix(&target);
        Controller {
            robot,
            target,
            kp: core::array::from_fn(|i| m[i][i] * OMEGA * OMEGA),
            kd: core::array::from_fn(|i| 2.0 * m[i][i] * OMEGA),
        }
    }

    /// One control period: the torques to apply for the measured `q`, `qd`.
    fn step(&self, q: &[f32; 6], qd: &[f32; 6]) -> [f32; 6] {
        let g = self.robot.gravity_torques(q);
        core::array::from_fn(|i| g[i] + self.kp[i] * (self.target[i] - q[i]) - self.kd[i] * qd[i])
    }
}

fn main() {
    let target = [0.5f32, -0.8, 0.6, 0.2, 0.4, -0.3];
    let controller = Controller::new(Puma560 { payload: 1.0 }, target);
    let plant = Puma560 { payload: 1.0 };
    let (mut q, mut qd) = ([0.0f64, -0.5, 0.9, 0.0, 0.6, 0.0], [0.0f64; 6]);
    let mut busy = std::time::Duration::ZERO;
    for k in 0..=2000 {
        let measured_q = q.map(|x| x as f32);
        let measured_qd = qd.map(|x| x as f32);
        let started = std::time::Instant::now();
        let tau = controller.step(&measured_q, &measured_qd);
        busy += started.elapsed();
        if k % 250 == 0 {
            let error = measured_q
                .iter()
                .zip(&target)
                .fold(0.0f32, |m, (a, b)| m.max((a - b).abs()));
            println!(
                "t = {:.2} s  largest joint error {error:.2e} rad  τ = {tau:.2?}",
                k as f32 * PERIOD
            );
        }
        let tau = tau.map(f64::from);
        plant.simulate(
            &mut q,
            &mut qd,
            &tau,
            f64::from(PERIOD) / SUBSTEPS as f64,
            SUBSTEPS,
        );
    }
    println!(
        "controller: {:.0} ns per period on average (gravity torques and the PD term, f32)",
        busy.as_nanos() as f64 / 2001.0
    );
}
