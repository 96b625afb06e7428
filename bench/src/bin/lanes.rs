//! Throughput of the lane types: PUMA 560's and the Panda's generated methods per state, one
//! state a call (`f64`, `f32`) against four or eight (`F64x4`, `F32x8`: one AVX register each
//! where the build enables AVX2, two SSE2 registers otherwise), in Rust alone.
//!
//! ```text
//! RUSTFLAGS="-C target-cpu=native" cargo run --release -p dynamics-bench --bin lanes
//! ```
//!
//! 64 states (q, q̇, q̈ uniform in ±1.5, drawn by a fixed generator), gathered four or eight at a
//! time into lanes beforehand. A round times each variant on all 64 states, 200 times over, the
//! variants interleaved; the figure is the median over 31 rounds of the time per state. Inputs
//! and whole results go through `std::hint::black_box`. No timing asserts: a measurement, not a
//! test.

use dynamics_bench::{Panda, Puma560};
use dynamics_runtime::lanes::{gather, Lanes};
use dynamics_runtime::{DynamicsDerivatives, F32x8, F64x4, F64x8, Real, RealScalar};
use std::hint::black_box;
use std::time::Instant;

const STATES: usize = 64;
const REPEATS: usize = 200;
const ROUNDS: usize = 31;

/// `q`, `q̇`, `q̈` of one state.
type State<E, const N: usize> = [[E; N]; 3];

/// The states, drawn by SplitMix64.
fn states<E: RealScalar, const N: usize>() -> Vec<State<E, N>> {
    let mut s = 0x5eed_u64;
    let mut draw = move || {
        s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        #[allow(clippy::cast_precision_loss)]
        let unit = ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64;
        E::from_f64(3.0 * unit - 1.5)
    };
    (0..STATES)
        .map(|_| core::array::from_fn(|_| core::array::from_fn(|_| draw())))
        .collect()
}

/// The states `L` at a time in lanes.
fn lanes<V: Lanes<L>, const L: usize, const N: usize>(
    states: &[State<V::Scalar, N>],
) -> Vec<State<V, N>> {
    states
        .chunks_exact(L)
        .map(|c| core::array::from_fn(|k| gather(&core::array::from_fn(|l| c[l][k]))))
        .collect()
}

/// One method of the robot on one call's inputs, its whole result through `black_box` (a part
/// of it would let the compiler drop the code of the rest).
type Method<T, const N: usize> = fn(&State<T, N>);

/// `τ`.
fn tau<R: DynamicsDerivatives<N> + Default, T: Real, const N: usize>(s: &State<T, N>) {
    black_box(R::default().inverse_dynamics(&s[0], &s[1], &s[2]));
}

/// `M`.
fn mass<R: DynamicsDerivatives<N> + Default, T: Real, const N: usize>(s: &State<T, N>) {
    black_box(R::default().mass_matrix(&s[0]));
}

/// `q̈`, the state's `q̈` as torques.
fn forward<R: DynamicsDerivatives<N> + Default, T: Real, const N: usize>(s: &State<T, N>) {
    black_box(R::default().forward_dynamics(&s[0], &s[1], &s[2]).ok());
}

/// `∂τ/∂q`, `∂τ/∂q̇`.
fn dtau<R: DynamicsDerivatives<N> + Default, T: Real, const N: usize>(s: &State<T, N>) {
    black_box(R::default().inverse_dynamics_derivatives(&s[0], &s[1], &s[2]));
}

/// The methods timed.
fn methods<R: DynamicsDerivatives<N> + Default, T: Real, const N: usize>(
) -> [(&'static str, Method<T, N>); 4] {
    [
        ("inverse_dynamics", tau::<R, T, N>),
        ("mass_matrix", mass::<R, T, N>),
        ("forward_dynamics", forward::<R, T, N>),
        ("inverse_dynamics_derivatives", dtau::<R, T, N>),
    ]
}

/// Nanoseconds per state of `f` over `calls` (each of `per_call` states).
fn time<T: Real, const N: usize>(f: Method<T, N>, calls: &[State<T, N>], per_call: usize) -> f64 {
    let start = Instant::now();
    for _ in 0..REPEATS {
        for c in calls {
            f(black_box(c));
        }
    }
    #[allow(clippy::cast_precision_loss)]
    let states = (REPEATS * calls.len() * per_call) as f64;
    start.elapsed().as_secs_f64() * 1e9 / states
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The medians of one precision: one state a call (`T`) against lanes (`V`).
fn compare<R, T, V, const L: usize, const N: usize>(robot: &str, precision: &str)
where
    R: DynamicsDerivatives<N> + Default,
    T: RealScalar,
    V: Lanes<L, Scalar = T>,
{
    let singles = states::<T, N>();
    let wide = lanes::<V, L, N>(&singles);
    for ((name, one), (_, many)) in methods::<R, T, N>().into_iter().zip(methods::<R, V, N>()) {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for _ in 0..ROUNDS {
            a.push(time(one, &singles, 1));
            b.push(time(many, &wide, L));
        }
        let (a, b) = (median(a), median(b));
        println!(
            "{robot:<8} {name:<30} {precision}: {a:7.1} ns/state one at a time, {b:7.1} ns/state in {L} lanes ({:.2}×)",
            a / b
        );
    }
}

fn main() {
    println!(
        "{} build",
        if cfg!(target_feature = "avx2") {
            "AVX2"
        } else {
            "baseline (no AVX2)"
        }
    );
    compare::<Puma560, f64, F64x4, 4, 6>("puma560", "f64");
    compare::<Puma560, f64, F64x8, 8, 6>("puma560", "f64");
    compare::<Puma560, f32, F32x8, 8, 6>("puma560", "f32");
    compare::<Panda, f64, F64x4, 4, 7>("panda", "f64");
    compare::<Panda, f64, F64x8, 8, 7>("panda", "f64");
    compare::<Panda, f32, F32x8, 8, 7>("panda", "f32");
}
