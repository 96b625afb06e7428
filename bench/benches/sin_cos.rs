//! Criterion benchmark of `dynamics_runtime::Real::sin_cos` (the crate's own shared sine and
//! cosine, which generated code calls once per revolute joint) against std's `sin_cos`
//! (glibc on Linux), for `f64` and `f32`.
//!
//! Each measurement is six pairs, one per joint of a 6-joint arm, at fixed angles spread over
//! [−π, π] and a little beyond (as joint angles are): the calls are independent, as in
//! generated code, so the processor may overlap them.
//!
//! Run with `cargo bench -p dynamics-bench --bench sin_cos` (about 10 s).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use dynamics_runtime::Real;

const ANGLES: [f64; 6] = [0.1, -0.4, 2.3, -3.0, 0.5, 4.2];

fn own<T: Real>(q: &[T; 6]) -> [(T, T); 6] {
    q.map(Real::sin_cos)
}

fn bench(c: &mut Criterion) {
    let q64 = ANGLES;
    #[allow(clippy::cast_possible_truncation)]
    let q32 = ANGLES.map(|x| x as f32);

    let mut g = c.benchmark_group("sin_cos_f64");
    g.throughput(Throughput::Elements(6));
    g.bench_function("own", |b| b.iter(|| own(black_box(&q64))));
    g.bench_function("std", |b| b.iter(|| black_box(&q64).map(f64::sin_cos)));
    g.finish();

    let mut g = c.benchmark_group("sin_cos_f32");
    g.throughput(Throughput::Elements(6));
    g.bench_function("own", |b| b.iter(|| own(black_box(&q32))));
    g.bench_function("std", |b| b.iter(|| black_box(&q32).map(f32::sin_cos)));
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(30)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300))
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
