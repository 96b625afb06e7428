//! Sizing the PUMA 560's actuators for a pick-and-place cycle: the torque each joint needs
//! (peak and RMS), its peak mechanical power `τ q̇`, and which term of
//! `τ = M(q) q̈ + C(q, q̇) q̇ + g(q) + τ_f(q̇)` sets the peak, from the generated methods.
//!
//! The cycle: home → above the part → down to grasp → up with a 2.5 kg part → over the place
//! → down to release → home empty, each leg a quintic rest-to-rest move, sampled at 1 kHz.
//!
//! Run with `cargo run --release -p dynamics-examples --example size_puma560`.

use dynamics_examples::Puma560;
use dynamics_runtime::Dynamics;

/// (end pose in rad, duration in s, payload carried in kg).
const LEGS: [([f64; 6], f64, f64); 6] = [
    ([0.9, -0.35, 0.55, 0.0, 0.9, 0.0], 1.2, 0.0),
    ([0.9, -0.15, 0.45, 0.0, 0.8, 0.0], 0.6, 0.0),
    ([0.9, -0.35, 0.55, 0.0, 0.9, 0.0], 0.6, 2.5),
    ([-0.7, -0.4, 0.7, 0.0, 0.8, 1.2], 1.4, 2.5),
    ([-0.7, -0.2, 0.6, 0.0, 0.7, 1.2], 0.6, 2.5),
    ([0.0, -0.6, 0.9, 0.0, 0.6, 0.0], 1.4, 0.0),
];
const HOME: [f64; 6] = [0.0, -0.6, 0.9, 0.0, 0.6, 0.0];
const RATE: f64 = 1000.0;

/// Per joint: peak |τ| (signed), its time and terms (inertial, Coriolis, gravity, friction),
/// ∫τ² dt, and the peak power.
#[derive(Clone, Copy, Default)]
struct Joint {
    peak: f64,
    at: f64,
    terms: [f64; 4],
    squares: f64,
    power: f64,
}

fn main() {
    let mut joints = [Joint::default(); 6];
    let (mut start, mut t) = (HOME, 0.0);
    for (end, duration, payload) in LEGS {
        let puma = Puma560 { payload };
        let steps = (duration * RATE) as usize;
        for k in 1..=steps {
            let s = k as f64 / steps as f64;
            let shape = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
            let rate = 30.0 * s * s * (1.0 - s) * (1.0 - s) / duration;
            let curvature = 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s) / (duration * duration);
            let q: [f64; 6] = core::array::from_fn(|i| start[i] + (end[i] - start[i]) * shape);
            let qd: [f64; 6] = core::array::from_fn(|i| (end[i] - start[i]) * rate);
            let qdd: [f64; 6] = core::array::from_fn(|i| (end[i] - start[i]) * curvature);
            let m = puma.mass_matrix(&q);
            let (c, g, f) = (
                puma.coriolis_torques(&q, &qd),
                puma.gravity_torques(&q),
                puma.friction_torques(&qd),
            );
            let tau = puma.inverse_dynamics(&q, &qd, &qdd);
            for i in 0..6 {
                let inertial: f64 = (0..6).map(|j| m[i][j] * qdd[j]).sum();
                let terms = [inertial, c[i], g[i], f[i]];
                // The split adds up to the generated inverse dynamics.
                assert!((terms.iter().sum::<f64>() - tau[i]).abs() < 1e-9 * (1.0 + tau[i].abs()));
                let joint = &mut joints[i];
                if tau[i].abs() > joint.peak.abs() {
                    (joint.peak, joint.at, joint.terms) = (tau[i], t + s * duration, terms);
                }
                joint.squares += tau[i] * tau[i] / RATE;
                if (tau[i] * qd[i]).abs() > joint.power.abs() {
                    joint.power = tau[i] * qd[i];
                }
            }
        }
        (start, t) = (end, t + duration);
    }
    println!("PUMA 560, pick-and-place cycle of {t:.1} s (2.5 kg part), sampled at {RATE} Hz");
    println!(
        "joint   peak τ (N m)  at t (s)  RMS τ (N m)  peak power (W) | share at peak: inertial  Coriolis  gravity  friction"
    );
    for (i, j) in joints.iter().enumerate() {
        let share = j.terms.map(|x| 100.0 * x / j.peak);
        println!(
            "{:>5} {:>14.3} {:>9.3} {:>12.3} {:>15.3} | {:>22.1} % {:>7.1} % {:>6.1} % {:>7.1} %",
            i + 1,
            j.peak,
            j.at,
            (j.squares / t).sqrt(),
            j.power,
            share[0],
            share[1],
            share[2],
            share[3]
        );
    }
}
