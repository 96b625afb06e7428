//! Four and eight arguments at once (`Real::sin_cos_4`, `Real::sin_cos_8`) equal one at a time,
//! bit for bit, in and out of the fast range: part of the `trig` test, which `.ci/run` also runs
//! built for the native CPU (the AVX2 lanes).

use super::{BOUND_F32, BOUND_F64};
use dynamics_runtime::Real;

/// Asserts that `sin_cos_4` of the four arguments `$x` (of type `$t`) equals `Real::sin_cos` of
/// each, bit for bit.
macro_rules! assert_four_equal_one {
    ($t:ty, $x:expr) => {{
        let x: [$t; 4] = $x;
        let (s4, c4) = <$t>::sin_cos_4(x);
        for k in 0..4 {
            let (s, c) = Real::sin_cos(x[k]);
            assert_eq!(
                (s4[k].to_bits(), c4[k].to_bits()),
                (s.to_bits(), c.to_bits()),
                "{x:?}"
            );
        }
    }};
}

/// Four at once equals one at a time, bit for bit, in and out of the fast range. On x86-64 this
/// checks the vector paths: SSE2 pairs for `f64` and SSE quads for `f32` in a default build, AVX2
/// lanes for `f64` with `RUSTFLAGS="-C target-cpu=native"` (`.ci/run` runs it both ways).
#[test]
fn four_at_once_equal_one_at_a_time() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    #[allow(clippy::cast_precision_loss)]
    for round in 0..100_000 {
        let mut x = [0.0f64; 4];
        for v in &mut x {
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            *v = match round % 4 {
                0 => (u - 0.5) * 20.0,
                1 => (u - 0.5) * 2.0 * 65_536.0,
                2 => (u - 0.5) * 1e-6,
                _ => (u - 0.5) * 1e6,
            };
        }
        assert_four_equal_one!(f64, x);
        assert_four_equal_one!(f32, x.map(|v| v as f32));
    }
    // The edges of the fast range, where the four-lane test decides between the paths.
    let tiny = 2f64.powi(-27); // `TINY_F64`
    let edges = [
        tiny,
        -tiny,
        f64::from_bits(tiny.to_bits() - 1),
        BOUND_F64,
        -BOUND_F64,
        f64::from_bits(BOUND_F64.to_bits() + 1),
        0.0,
        -0.0,
        f64::NAN,
        f64::INFINITY,
        1.0,
        -2.5,
    ];
    for (i, &a) in edges.iter().enumerate() {
        for &b in &edges[i..] {
            assert_four_equal_one!(f64, [a, 1.0, b, -0.5]);
        }
    }
    let tiny = 2f32.powi(-12); // `TINY_F32`
    let edges = [
        tiny,
        -tiny,
        f32::from_bits(tiny.to_bits() - 1),
        BOUND_F32,
        -BOUND_F32,
        f32::from_bits(BOUND_F32.to_bits() + 1),
        0.0,
        f32::NAN,
        f32::NEG_INFINITY,
        1.0,
    ];
    for (i, &a) in edges.iter().enumerate() {
        for &b in &edges[i..] {
            assert_four_equal_one!(f32, [a, 1.0, b, -0.5]);
        }
    }
}

/// Asserts that `sin_cos_8` of the eight arguments `$x` (of type `$t`) equals `Real::sin_cos` of
/// each, bit for bit.
macro_rules! assert_eight_equal_one {
    ($t:ty, $x:expr) => {{
        let x: [$t; 8] = $x;
        let (s8, c8) = <$t>::sin_cos_8(x);
        for k in 0..8 {
            let (s, c) = Real::sin_cos(x[k]);
            assert_eq!(
                (s8[k].to_bits(), c8[k].to_bits()),
                (s.to_bits(), c.to_bits()),
                "{x:?}"
            );
        }
    }};
}

/// Eight at once equals one at a time, bit for bit: the two vectors behind one range test, and
/// the fallback when any one of the eight arguments, in either half, leaves the fast range.
#[test]
fn eight_at_once_equal_one_at_a_time() {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    #[allow(clippy::cast_precision_loss)]
    for round in 0..50_000 {
        let mut x = [0.0f64; 8];
        for v in &mut x {
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            *v = match round % 3 {
                0 => (u - 0.5) * 20.0,
                1 => (u - 0.5) * 2.0 * 65_536.0,
                _ => (u - 0.5) * 1e6,
            };
        }
        assert_eight_equal_one!(f64, x);
        assert_eight_equal_one!(f32, x.map(|v| v as f32));
    }
    let outside_f64 = [
        0.0,
        1e-300,
        f64::from_bits(BOUND_F64.to_bits() + 1),
        f64::NAN,
        f64::INFINITY,
    ];
    let outside_f32 = [
        0.0,
        1e-30,
        f32::from_bits(BOUND_F32.to_bits() + 1),
        f32::NAN,
        f32::INFINITY,
    ];
    for k in 0..8 {
        for (&a, &b) in outside_f64.iter().zip(&outside_f32) {
            let mut x = [0.3, -1.2, 2.5, 4.0, -0.7, 1.5, 3.1, -2.2];
            x[k] = a;
            assert_eight_equal_one!(f64, x);
            let mut x = [0.3f32, -1.2, 2.5, 4.0, -0.7, 1.5, 3.1, -2.2];
            x[k] = b;
            assert_eight_equal_one!(f32, x);
        }
    }
}
