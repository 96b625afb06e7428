//! Criterion benchmarks: the generated dynamics against the other implementations in this
//! workspace, on the four 6-joint reference robots and the 7-joint Panda.
//!
//! One group per robot (`puma560`, `stanford`, `ur5`, `random5`, `panda`), each measuring, at
//! one fixed state taken from the robot's reference data:
//!
//! * `inverse_dynamics`, `mass_matrix`, `coriolis_matrix`, `gravity_torques`: the generated
//!   closed-form `f64` methods of `#[derive(Dynamics)]`;
//! * `numeric_rnea`: a plain numeric recursive Newton-Euler
//!   (`dynamics_codegen::numeric::Numeric::inverse_dynamics`, loops over joints at run time,
//!   allocates its `Vec`s on every call);
//! * `book_inverse_dynamics`: the book's O(n⁴) Lagrangian method (`dynamics-reference`), with
//!   fewer samples since one call takes far longer.
//!
//! Run with `cargo bench -p dynamics-bench` (about a minute). The numbers compared with
//! Pinocchio come from `bench/run` instead, whose C++ program times both sides in turn.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use dynamics_bench::{Panda, Puma560, Random5, Stanford, Ur5};
use dynamics_runtime::Dynamics;

/// Index of the reference sample used as the fixed input (sample 0 is the zero state).
const SAMPLE: usize = 7;

fn group<R: Dynamics<N>, const N: usize>(c: &mut Criterion, name: &str, robot: &R) {
    let samples = dynamics_bench::samples::<N>(name);
    let s = samples[SAMPLE];
    let numeric = dynamics_bench::numeric(name);
    let book = dynamics_bench::book(name);
    let (q, qd, qdd) = (&s.q, &s.qd, &s.qdd);

    let mut g = c.benchmark_group(name);
    g.bench_function("inverse_dynamics", |b| {
        b.iter(|| robot.inverse_dynamics(black_box(q), black_box(qd), black_box(qdd)));
    });
    g.bench_function("mass_matrix", |b| {
        b.iter(|| robot.mass_matrix(black_box(q)));
    });
    g.bench_function("coriolis_matrix", |b| {
        b.iter(|| robot.coriolis_matrix(black_box(q), black_box(qd)));
    });
    g.bench_function("gravity_torques", |b| {
        b.iter(|| robot.gravity_torques(black_box(q)));
    });
    g.bench_function("numeric_rnea", |b| {
        b.iter(|| numeric.inverse_dynamics(black_box(q), black_box(qd), black_box(qdd)));
    });
    // The settings below apply to the benchmarks that follow them in this group.
    g.sample_size(10)
        .measurement_time(Duration::from_millis(500));
    g.bench_function("book_inverse_dynamics", |b| {
        b.iter(|| book.inverse_dynamics(black_box(q), black_box(qd), black_box(qdd)));
    });
    g.finish();
}

fn robots(c: &mut Criterion) {
    group(c, "puma560", &Puma560);
    group(c, "stanford", &Stanford);
    group(c, "ur5", &Ur5);
    group(c, "random5", &Random5);
    group(c, "panda", &Panda);
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .measurement_time(Duration::from_secs(1))
        .warm_up_time(Duration::from_millis(300))
}

criterion_group! {
    name = benches;
    config = config();
    targets = robots
}
criterion_main!(benches);
