//! Scaling of `InParallel` (the `rayon` feature): the batch methods of PUMA 560 and the Panda on
//! one thread against rayon's pool, per state, at several batch lengths.
//!
//! ```text
//! RUSTFLAGS="-C target-cpu=native" cargo run --release -p dynamics-bench --bin threads
//! ```
//!
//! States uniform in ±1.5 from a fixed generator, in a slice of states; results into a slice of
//! results. A round times both variants in turn; the figure is the median over 15 rounds. No
//! timing asserts: a measurement, not a test.

use dynamics_bench::{Panda, Puma560};
use dynamics_runtime::{DynamicsBatch, DynamicsDerivatives, DynamicsDerivativesBatch, InParallel};
use std::hint::black_box;
use std::time::Instant;

const ROUNDS: usize = 15;
/// States evaluated per measurement at least, so that short batches are timed over many calls.
const WORK: usize = 200_000;

/// `count` states, uniform in ±1.5.
fn states<const N: usize>(count: usize, seed: u64) -> Vec<[f64; N]> {
    let mut x = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        #[allow(clippy::cast_precision_loss)]
        let unit = (x >> 11) as f64 / (1_u64 << 53) as f64;
        3.0 * unit - 1.5
    };
    (0..count)
        .map(|_| core::array::from_fn(|_| next()))
        .collect()
}

/// Nanoseconds per state of `f`, called enough times for [`WORK`] states.
fn time(len: usize, mut f: impl FnMut()) -> f64 {
    let calls = WORK.div_ceil(len);
    let start = Instant::now();
    for _ in 0..calls {
        f();
    }
    #[allow(clippy::cast_precision_loss)]
    let states = (calls * len) as f64;
    start.elapsed().as_secs_f64() * 1e9 / states
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One line per method and length: one thread, the pool, the ratio.
fn compare<R, const N: usize>(robot: &R, name: &str)
where
    R: DynamicsDerivatives<N> + Sync,
{
    for len in [100, 1_000, 10_000, 100_000] {
        let (q, qd, qdd) = (
            states::<N>(len, 1),
            states::<N>(len, 2),
            states::<N>(len, 3),
        );
        let mut tau = vec![[0.0; N]; len];
        let zero = [0.0; N];
        let mut d = vec![robot.inverse_dynamics_derivatives(&zero, &zero, &zero); len];
        let mut rows: [(&str, Vec<f64>, Vec<f64>); 2] = [
            ("inverse_dynamics", vec![], vec![]),
            ("inverse_dynamics_derivatives", vec![], vec![]),
        ];
        for _ in 0..ROUNDS {
            rows[0].1.push(time(len, || {
                robot.inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
                black_box(&tau);
            }));
            rows[0].2.push(time(len, || {
                InParallel(robot).inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
                black_box(&tau);
            }));
            rows[1].1.push(time(len, || {
                robot.inverse_dynamics_derivatives_batch(&q[..], &qd[..], &qdd[..], &mut d[..]);
                black_box(&d);
            }));
            rows[1].2.push(time(len, || {
                InParallel(robot).inverse_dynamics_derivatives_batch(
                    &q[..],
                    &qd[..],
                    &qdd[..],
                    &mut d[..],
                );
                black_box(&d);
            }));
        }
        for (method, one, pool) in rows {
            let (one, pool) = (median(one), median(pool));
            println!(
                "{name:<8} {method:<30} {len:>7} states: {one:7.1} ns/state on one thread, {pool:7.1} on {} threads ({:.2}×)",
                rayon::current_num_threads(),
                one / pool
            );
        }
    }
}

fn main() {
    compare(&Puma560, "puma560");
    compare(&Panda, "panda");
}
