//! The quintic rest-to-rest move: `q(t) = q_0 + (q_f − q_0)(10 s³ − 15 s⁴ + 6 s⁵)`,
//! `s = t / T`, with zero velocity and acceleration at both ends (the fifth-order polynomial of
//! trajectory planning).

use super::Sample;

/// The quintic rest-to-rest move from `from` to `to` in `duration` seconds, `samples` samples
/// evenly spaced (both ends included), each passed to `each`.
pub fn quintic(
    from: &[f64],
    to: &[f64],
    duration: f64,
    samples: usize,
    mut each: impl FnMut(&Sample),
) {
    let n = from.len();
    let mut s = Sample {
        t: 0.0,
        q: vec![0.0; n],
        qd: vec![0.0; n],
        qdd: vec![0.0; n],
        tau: Vec::new(),
        line: 0,
        given: super::Given::Accelerations,
    };
    let last = samples.max(2) - 1;
    for k in 0..=last {
        let x = k as f64 / last as f64;
        let shape = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
        let rate = 30.0 * x * x * (1.0 - x) * (1.0 - x) / duration;
        let curvature = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration * duration);
        s.t = x * duration;
        for j in 0..n {
            let d = to[j] - from[j];
            s.q[j] = from[j] + d * shape;
            s.qd[j] = d * rate;
            s.qdd[j] = d * curvature;
        }
        each(&s);
    }
}
