//! `Real::sin_cos` (this crate's own shared sine and cosine) against std (glibc on Linux) and
//! against correctly rounded values computed with mpmath, over the whole range of `f64` and
//! `f32`: random arguments of every magnitude, a dense sweep of four turns, the arguments
//! nearest multiples of π/4 and π/2 (where the range reduction cancels most), ±0, subnormals,
//! either side of the fast path's bound, huge values, NaN and ±∞.
//!
//! Errors are in ulps of the reference value: for `f32`, the `f64` std result, unrounded, in
//! `f32` ulps. `cargo test -p dynamics-runtime --test it trig:: -- --nocapture` prints the worst
//! cases; `-- --ignored` also runs the exhaustive test of every `f32` of the fast range.

use dynamics_runtime::Real;
use dynamics_test_support::Rng;

mod lanes;

use crate::ulp::{err_f32, err_f64, see_f32, see_f64, Worst};

/// Fast path bounds (`src/trig/reduction.rs`).
const BOUND_F64: f64 = 65_536.0;
const BOUND_F32: f32 = 4_096.0;

/// Allowed error against std in the fast range, where std (glibc) is itself within 1 ulp. `f64`:
/// 2 ulps since the kernels dropped the reduction's tail `r_lo` (2026-11-29); measured 2 in the
/// default build (multiply-adds in two roundings) and 1 with FMA on [−4π, 4π].
const MAX_ULP_F64: f64 = 2.0;
const MAX_ULP_F32: f64 = 1.0;
/// Allowed error beyond it, where `libm` (musl's algorithms) and glibc may each be off by
/// nearly 1 ulp, in opposite directions.
const MAX_ULP_SLOW: f64 = 2.0;

/// The doubles closest to a multiple of π/2 in the fast range (the 12 smallest |x − kπ/2|),
/// with their sine and cosine correctly rounded, from mpmath at 400 bits.
const HARD_F64: [(u64, u64, u64); 12] = [
    (0x4046C6CBC45DC8DE, 0x3FF0000000000000, 0xBC26D61B58C99C43), // x = 45.553093477052 (k = 29): sin = 1.0, cos = -6.189806365883577e-19
    (0x4056C6CBC45DC8DE, 0xBC36D61B58C99C43, 0xBFF0000000000000), // x = 91.106186954104 (k = 58): sin = -1.2379612731767154e-18, cos = -1.0
    (0x4066C6CBC45DC8DE, 0x3C46D61B58C99C43, 0x3FF0000000000000), // x = 182.212373908208 (k = 116): sin = 2.475922546353431e-18, cos = 1.0
    (0x4076C6CBC45DC8DE, 0x3C56D61B58C99C43, 0x3FF0000000000000), // x = 364.424747816416 (k = 232): sin = 4.951845092706862e-18, cos = 1.0
    (0x4086C6CBC45DC8DE, 0x3C66D61B58C99C43, 0x3FF0000000000000), // x = 728.849495632832 (k = 464): sin = 9.903690185413723e-18, cos = 1.0
    (0x4096C6CBC45DC8DE, 0x3C76D61B58C99C43, 0x3FF0000000000000), // x = 1457.698991265664 (k = 928): sin = 1.9807380370827447e-17, cos = 1.0
    (0x40A6C6CBC45DC8DE, 0x3C86D61B58C99C43, 0x3FF0000000000000), // x = 2915.397982531328 (k = 1856): sin = 3.9614760741654893e-17, cos = 1.0
    (0x3FF921FB54442D18, 0x3FF0000000000000, 0x3C91A62633145C07), // x = 1.5707963267948966 (k = 1): sin = 1.0, cos = 6.123233995736766e-17
    (0x40B6C6CBC45DC8DE, 0x3C96D61B58C99C43, 0x3FF0000000000000), // x = 5830.795965062656 (k = 3712): sin = 7.922952148330979e-17, cos = 1.0
    (0x400921FB54442D18, 0x3CA1A62633145C07, 0xBFF0000000000000), // x = 3.141592653589793 (k = 2): sin = 1.2246467991473532e-16, cos = -1.0
    (0x40E67E57CDD4DC54, 0xBFF0000000000000, 0x3CA396F53352C401), // x = 46066.74387591393 (k = 29327): sin = -1.0, cos = 1.3593070393188837e-16
    (0x40C6C6CBC45DC8DE, 0x3CA6D61B58C99C43, 0x3FF0000000000000), // x = 11661.591930125313 (k = 7424): sin = 1.5845904296661957e-16, cos = 1.0
];
/// The same for `f32` (the 12 closest), rounded to `f32`.
const HARD_F32: [(u32, u32, u32); 12] = [
    (0x437CE5F1, 0x3F800000, 0xB18FD1DE), // x = 252.89820861816406 (k = 161): sin = 1.0, cos = -4.185706892201324e-09
    (0x43FCE5F1, 0xB20FD1DE, 0xBF800000), // x = 505.7964172363281 (k = 322): sin = -8.371413784402648e-09, cos = -1.0
    (0x4096CBE4, 0xBF800000, 0x324CDE2E), // x = 4.71238899230957 (k = 3): sin = -1.0, cos = 1.1924880638503055e-08
    (0x447CE5F1, 0x328FD1DE, 0x3F800000), // x = 1011.5928344726562 (k = 644): sin = 1.6742827568805296e-08, cos = 1.0
    (0x4116CBE4, 0xB2CCDE2E, 0xBF800000), // x = 9.42477798461914 (k = 6): sin = -2.384976127700611e-08, cos = -1.0
    (0x44FCE5F1, 0x330FD1DE, 0x3F800000), // x = 2023.1856689453125 (k = 1288): sin = 3.348565513761059e-08, cos = 1.0
    (0x416231D6, 0x3F800000, 0xB319A6A2), // x = 14.137166976928711 (k = 9): sin = 1.0, cos = -3.5774640139152325e-08
    (0x3FC90FDB, 0x3F800000, 0xB33BBD2E), // x = 1.5707963705062866 (k = 1): sin = 1.0, cos = -4.371138828673793e-08
    (0x4196CBE4, 0x334CDE2E, 0x3F800000), // x = 18.84955596923828 (k = 12): sin = 4.769952255401222e-08, cos = 1.0
    (0x450BE628, 0x3F800000, 0x3377F042), // x = 2238.384765625 (k = 1425): sin = 1.0, cos = 5.77276821900341e-08
    (0x41BC7EDD, 0xBF800000, 0x33800ADD), // x = 23.56194496154785 (k = 15): sin = -1.0, cos = 5.962440496887211e-08
    (0x457CE5F1, 0x338FD1DE, 0x3F800000), // x = 4046.371337890625 (k = 2576): sin = 6.697131027522119e-08, cos = 1.0
];

fn in_fast_f64(x: f64) -> bool {
    x.abs() <= BOUND_F64
}

#[test]
fn f64_random_over_all_exponents() {
    let mut rng = Rng::new(1);
    let (mut fast, mut slow) = (Worst::default(), Worst::default());
    for _ in 0..400_000 {
        let x = rng.log_uniform(0..=2046);
        see_f64(if in_fast_f64(x) { &mut fast } else { &mut slow }, x);
    }
    // The magnitudes that matter most: 2^-30 to 2^17.
    for _ in 0..400_000 {
        let x = rng.log_uniform(993..=1040);
        see_f64(if in_fast_f64(x) { &mut fast } else { &mut slow }, x);
    }
    fast.check("f64, random, |x| <= 2^16", MAX_ULP_F64);
    slow.check("f64, random, |x| > 2^16", MAX_ULP_SLOW);
}

#[test]
fn f32_random_over_all_exponents() {
    let mut rng = Rng::new(2);
    let (mut fast, mut slow) = (Worst::default(), Worst::default());
    for _ in 0..400_000 {
        let bits = rng.next_u64() as u32;
        let x = f32::from_bits(bits & 0x807F_FFFF | ((bits >> 8) % 255) << 23);
        see_f32(
            if x.abs() <= BOUND_F32 {
                &mut fast
            } else {
                &mut slow
            },
            x,
        );
    }
    for _ in 0..400_000 {
        #[allow(clippy::cast_possible_truncation)]
        let x = rng.log_uniform(993..=1035) as f32;
        see_f32(
            if x.abs() <= BOUND_F32 {
                &mut fast
            } else {
                &mut slow
            },
            x,
        );
    }
    fast.check("f32, random, |x| <= 2^12", MAX_ULP_F32);
    slow.check("f32, random, |x| > 2^12", MAX_ULP_SLOW);
}

#[test]
fn dense_over_four_turns() {
    use std::f64::consts::PI;
    let (mut wide, mut narrow) = (Worst::default(), Worst::default());
    let n = 1_000_000;
    for i in 0..=n {
        let x = -4.0 * PI + 8.0 * PI * f64::from(i) / f64::from(n);
        see_f64(&mut wide, x);
        #[allow(clippy::cast_possible_truncation)]
        see_f32(&mut narrow, x as f32);
    }
    wide.check("f64, [-4π, 4π]", MAX_ULP_F64);
    narrow.check("f32, [-4π, 4π]", MAX_ULP_F32);
}

/// `x` moved by `steps` representable values (towards +∞ for positive `steps`).
fn step_f64(x: f64, steps: i64) -> f64 {
    let ordered = |b: u64| {
        if b >> 63 == 0 {
            b as i64
        } else {
            -((b & !(1 << 63)) as i64)
        }
    };
    let o = ordered(x.to_bits()) + steps;
    if o >= 0 {
        f64::from_bits(o as u64)
    } else {
        f64::from_bits((-o) as u64 | 1 << 63)
    }
}

fn step_f32(x: f32, steps: i32) -> f32 {
    let ordered = |b: u32| {
        if b >> 31 == 0 {
            b as i32
        } else {
            -((b & !(1 << 31)) as i32)
        }
    };
    let o = ordered(x.to_bits()) + steps;
    if o >= 0 {
        f32::from_bits(o as u32)
    } else {
        f32::from_bits((-o) as u32 | 1 << 31)
    }
}

#[test]
fn near_multiples_of_quarter_pi() {
    use std::f64::consts::FRAC_PI_4;
    let (mut wide, mut narrow) = (Worst::default(), Worst::default());
    // Every multiple of π/4 up to 1000 turns for f64 (and all up to the f32 bound), then
    // random ones up to the bound; each with 8 neighbours on either side.
    let mut rng = Rng::new(3);
    let last = (BOUND_F64 / FRAC_PI_4) as i64;
    let ks = (-8000..=8000)
        .chain((0..20_000).map(|_| (rng.next_u64() % (2 * last as u64 + 1)) as i64 - last));
    for k in ks {
        let centre = k as f64 * FRAC_PI_4;
        for step in -8..=8 {
            let x = step_f64(centre, step);
            if in_fast_f64(x) {
                see_f64(&mut wide, x);
            }
            #[allow(clippy::cast_possible_truncation)]
            let xf = step_f32(centre as f32, step as i32);
            if xf.abs() <= BOUND_F32 {
                see_f32(&mut narrow, xf);
            }
        }
    }
    wide.check("f64, near kπ/4", MAX_ULP_F64);
    narrow.check("f32, near kπ/4", MAX_ULP_F32);
}

#[test]
fn hardest_reductions_against_mpmath() {
    for (x, sin, cos) in HARD_F64 {
        let x = f64::from_bits(x);
        for x in [x, -x] {
            let (s, c) = Real::sin_cos(x);
            let sign = if x < 0.0 { -1.0 } else { 1.0 };
            let want = (sign * f64::from_bits(sin), f64::from_bits(cos));
            assert!(
                err_f64(s, want.0) <= 0.5,
                "sin({x:e}) = {s:e}, want {:e}",
                want.0
            );
            assert!(
                err_f64(c, want.1) <= 0.5,
                "cos({x:e}) = {c:e}, want {:e}",
                want.1
            );
        }
    }
    for (x, sin, cos) in HARD_F32 {
        let x = f32::from_bits(x);
        for x in [x, -x] {
            let (s, c) = Real::sin_cos(x);
            let sign = if x < 0.0 { -1.0 } else { 1.0 };
            let want = (sign * f32::from_bits(sin), f32::from_bits(cos));
            // One ulp: the mpmath values are correctly rounded to f32.
            assert!(
                err_f32(s, f64::from(want.0)) <= 1.0,
                "sin({x:e}) = {s:e}, want {:e}",
                want.0
            );
            assert!(
                err_f32(c, f64::from(want.1)) <= 1.0,
                "cos({x:e}) = {c:e}, want {:e}",
                want.1
            );
        }
    }
}

#[test]
fn zeros_subnormals_and_tiny_arguments() {
    for x in [
        0.0,
        -0.0,
        f64::from_bits(1),
        -f64::from_bits(1),
        f64::MIN_POSITIVE,
        1e-300,
        -1e-20,
        7.4e-9,
    ] {
        let (s, c) = Real::sin_cos(x);
        assert_eq!(s.to_bits(), x.to_bits(), "sin({x:e})");
        assert_eq!(c, 1.0, "cos({x:e})");
        assert_eq!(
            (s.to_bits(), c),
            (x.sin().to_bits(), x.cos()),
            "std at {x:e}"
        );
    }
    for x in [
        0.0f32,
        -0.0,
        f32::from_bits(1),
        -f32::from_bits(1),
        f32::MIN_POSITIVE,
        1e-30,
        -2.4e-4,
    ] {
        let (s, c) = Real::sin_cos(x);
        assert_eq!(s.to_bits(), x.to_bits(), "sin({x:e})");
        assert_eq!(c, 1.0, "cos({x:e})");
    }
    // Either side of the tiny-argument threshold.
    let mut worst = Worst::default();
    for x in [2f64.powi(-27), 2f64.powi(-26), 1e-8, 3e-8] {
        for step in -4..=4 {
            see_f64(&mut worst, step_f64(x, step));
            see_f64(&mut worst, -step_f64(x, step));
        }
    }
    worst.check("f64, around 2^-27", MAX_ULP_F64);
    let mut worst = Worst::default();
    for x in [2f32.powi(-12), 2f32.powi(-11), 1e-4, 5e-4] {
        for step in -4..=4 {
            see_f32(&mut worst, step_f32(x, step));
            see_f32(&mut worst, -step_f32(x, step));
        }
    }
    worst.check("f32, around 2^-12", MAX_ULP_F32);
}

#[test]
fn either_side_of_the_bound_and_huge_values() {
    let mut worst = Worst::default();
    for step in -1000..=1000 {
        for x in [BOUND_F64, 41_722.5 * std::f64::consts::FRAC_PI_2] {
            see_f64(&mut worst, step_f64(x, step));
            see_f64(&mut worst, -step_f64(x, step));
        }
    }
    worst.check("f64, around 2^16", MAX_ULP_SLOW);
    let mut worst = Worst::default();
    for step in -1000..=1000 {
        see_f32(&mut worst, step_f32(BOUND_F32, step));
        see_f32(&mut worst, -step_f32(BOUND_F32, step));
    }
    worst.check("f32, around 2^12", MAX_ULP_SLOW);

    let mut worst = Worst::default();
    for x in [
        1e22,
        2f64.powi(52),
        2f64.powi(1000),
        1e300,
        f64::MAX,
        -f64::MAX,
    ] {
        see_f64(&mut worst, x);
    }
    worst.check("f64, huge", MAX_ULP_SLOW);
    let mut worst = Worst::default();
    for x in [1e10f32, 2f32.powi(24), 1e38, f32::MAX, -f32::MAX] {
        see_f32(&mut worst, x);
    }
    worst.check("f32, huge", MAX_ULP_SLOW);
}

#[test]
fn nan_and_infinities_give_nan() {
    for x in [f64::NAN, -f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (s, c) = Real::sin_cos(x);
        assert!(s.is_nan() && c.is_nan(), "sin_cos({x}) = ({s}, {c})");
        assert!(Real::sin(x).is_nan() && Real::cos(x).is_nan());
    }
    for x in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let (s, c) = Real::sin_cos(x);
        assert!(s.is_nan() && c.is_nan(), "sin_cos({x}) = ({s}, {c})");
    }
}

#[test]
fn pythagoras_symmetry_and_bounds() {
    let mut rng = Rng::new(4);
    for _ in 0..200_000 {
        let x = (rng.unit() * 2.0 - 1.0) * BOUND_F64 * rng.unit().powi(8);
        let (s, c) = Real::sin_cos(x);
        assert!(
            (s * s + c * c - 1.0).abs() <= 4.0 * f64::EPSILON,
            "x = {x:e}"
        );
        assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "x = {x:e}");
        let (sn, cn) = Real::sin_cos(-x);
        assert_eq!(
            (sn.to_bits(), cn.to_bits()),
            ((-s).to_bits(), c.to_bits()),
            "x = {x:e}"
        );
        assert_eq!((Real::sin(x), Real::cos(x)), (s, c));

        #[allow(clippy::cast_possible_truncation)]
        let x = x as f32;
        let (s, c) = Real::sin_cos(x);
        assert!(
            (s * s + c * c - 1.0).abs() <= 4.0 * f32::EPSILON,
            "x = {x:e}"
        );
        assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "x = {x:e}");
        let (sn, cn) = Real::sin_cos(-x);
        assert_eq!(
            (sn.to_bits(), cn.to_bits()),
            ((-s).to_bits(), c.to_bits()),
            "x = {x:e}"
        );
        assert_eq!((Real::sin(x), Real::cos(x)), (s, c));
    }
    // Signs by quadrant, away from the axes.
    for k in -40i32..40 {
        let x = (f64::from(k) + 0.5) * std::f64::consts::FRAC_PI_2;
        let (s, c) = Real::sin_cos(x);
        let quadrant = k.rem_euclid(4);
        assert_eq!(s > 0.0, quadrant < 2, "sin sign at {x}");
        assert_eq!(c > 0.0, quadrant == 0 || quadrant == 3, "cos sign at {x}");
    }
}

/// Every `f32` of the fast range, against std's `f64` result. About a minute in release:
/// `cargo test --release -p dynamics-runtime --test it trig:: -- --ignored --nocapture`.
#[test]
#[ignore = "exhaustive: about a minute in release mode"]
fn f32_exhaustive_fast_range() {
    let mut worst = Worst::default();
    let top = BOUND_F32.to_bits();
    for bits in 0..=top {
        let x = f32::from_bits(bits);
        see_f32(&mut worst, x);
        see_f32(&mut worst, -x);
    }
    worst.check("f32, every |x| <= 2^12", MAX_ULP_F32);
}
