//! Sine and cosine of one argument together, for `f64` and `f32`: one range reduction shared
//! by both, two polynomial kernels evaluated side by side, and a branch-free choice of quadrant (by a
//! table of 0 and ±1 coefficients).
//!
//! `x = k·π/2 + r` with `k` the integer nearest `x·2/π` and `|r| ≤ π/4` (a hair more when
//! `x·2/π` rounds across a half-integer, which the kernels tolerate). Then `sin x` and `cos x`
//! are `±sin r` or `±cos r`, chosen by `k mod 4`.
//!
//! **Reduction (Cody-Waite).** π/2 is split into parts `P1 + P2 + … ≈ π/2` whose leading
//! parts have so few significant bits that `k·P1`, `k·P2`, … are exact for every `k` of the
//! fast range; `x − k·P1` is then exact too (Sterbenz: `x` and `k·P1` are within a factor of
//! two). The rounding error of the next subtraction is recovered exactly with Fast2Sum or
//! TwoSum, so `r` comes out as an unevaluated sum `r + r_lo`. The parts, the bound and the
//! exactness conditions were checked with exact rational arithmetic over every `k` of the fast
//! range, at the double nearest each `k·π/2` (where `|r|` is smallest; the smallest of all is
//! 2^-60.5, at `x ≈ 45.55`, for `f64` and 2^-27.8, at `x ≈ 252.9`, for `f32`): the reduced
//! argument's relative error is below 2^-61 for `f64` and 2^-32 for `f32`.
//!
//! * `f64`: parts of 35, 35 and 53 bits, fast for `|x| ≤ 2^16` (`|k| < 2^16`).
//! * `f32`: parts of 12, 12, 12 and 22 bits, fast for `|x| ≤ 2^12` (`|k| < 2^12`), computed in
//!   `f32` throughout, for single-precision FPUs without `f64` hardware.
//!
//! **Kernels.** The minimax polynomials of fdlibm on [−π/4, π/4]: for `f64`, those of Sun's
//! `k_sin.c` and `k_cos.c` (fdlibm 5.3, 1993; both accurate to 2^-58), for `f32`, those of
//! FreeBSD's `k_sinf.c` and `k_cosf.c` (Bruce D. Evans, 2005), rounded to `f32`. Both are in
//! `z = r²`, evaluated in Estrin form on shared powers of `z`, and carry `r_lo` to first order:
//! `sin(r + r_lo) ≈ sin r + r_lo·(1 − z/2)`, `cos(r + r_lo) ≈ cos r − r·r_lo`.
//! `cos r = 1 − z/2 + …` adds the rounding error of `1 − z/2` back in (it is exact by Fast2Sum),
//! which keeps `cos` near π/4 within an ulp. Where the build has FMA (x86-64 with
//! `-C target-cpu=native` or `+fma`), the polynomials' multiply-adds are fused, and so are the
//! exact products `k·P1`, `k·P2` (and `k·P3` for `f32`) with their subtractions, which changes
//! no bit there, and `x·2/π` with the shift that rounds it to an integer: a shorter chain of
//! dependent operations, the same on the scalar and the vector paths. The generated code
//! waits for the sines and cosines before anything else, so each step off the chain counts
//! (random 6-joint robot: τ 89.6 → 87.4 ns for three fewer steps).
//!
//! **Outside the fast range.** Tiny arguments (`|x| < 2^-27`, `2^-12` for `f32`) return
//! `(x, 1)`, which is the correctly rounded result, keeps the sign of `±0` and never squares a
//! subnormal. Larger arguments than the bound, `±∞` and NaN go to `libm` (NaN in, NaN out).
//!
//! Measured on x86-64 (AMD EPYC, glibc 2.35): the error against correctly rounded values
//! (mpmath) is at most 0.76 ulp for `f64` (200,000 random arguments of the fast range; 2.7 %
//! of results differ from glibc's, by 1 ulp) and 0.83 ulp for `f32` (every `f32` of the fast
//! range, against the `f64` result); see `tests/trig.rs`. Cost: 71 instructions a pair for
//! `f64` (glibc's `sincos`: 99), about 10 ns against 12 ns; glibc's `sincosf` (which computes
//! in `f64`) remains faster than this `f32` path on such a machine.
//!
//! **Four at once** (`Real::sin_cos_4`, which generated code calls for groups of four joints):
//! on x86-64 the same operations run in vector lanes, bit for bit the results of one at a time.
//! `f64` uses the four lanes of AVX2 where the build enables it (`-C target-cpu=native`), else
//! two SSE2 registers of two lanes, which every x86-64 build has; `f32` uses the four lanes of
//! SSE. Elsewhere, and whenever an argument is outside the fast range, one at a time.

// Constants are written as published (kernels) or as exact decimal expansions (parts of π/2).
#![allow(clippy::excessive_precision)]

/// `1.5·2^52`: adding it rounds a double of magnitude below 2^51 to an integer, which lands
/// in the low bits of the sum's representation (`2^51 + k`, so the two lowest bits are
/// `k mod 4`).
const SHIFT_F64: f64 = 6_755_399_441_055_744.0;
/// `1.5·2^23`, the same for `f32`.
const SHIFT_F32: f32 = 12_582_912.0;

/// `f64`: below this, `(x, 1)` is the correctly rounded result (`x³/6` and `x²/2` are under
/// half an ulp of `x` and of 1).
const TINY_F64: f64 = 7.450_580_596_923_828e-9; // 2^-27
/// `f64`: the fast path's bound, 2^16 (`|k| ≤ 41722 < 2^16`).
const BOUND_F64: f64 = 65_536.0;
/// `f32`: 2^-12, as [`TINY_F64`].
const TINY_F32: f32 = 2.441_406_25e-4;
/// `f32`: the fast path's bound, 2^12 (`|k| ≤ 2608 < 2^12`).
const BOUND_F32: f32 = 4_096.0;

// π/2 = P1 + P2 + P3 + 5.3e-40 for f64. P1 and P2 have 35 significant bits, so k·P1 and k·P2
// are exact for |k| < 2^18.
const P1_F64: f64 = 1.570_796_326_792_333_3; // 0x1.921fb5444p+0
const P2_F64: f64 = 2.563_344_151_583_955_8e-12; // 0x1.68c234c4cp-39
const P3_F64: f64 = 1.056_299_906_698_742_8e-23; // 0x1.98a2e03707345p-77

// π/2 = P1 + P2 + P3 + P4 + 2.0e-21 for f32. P1, P2 and P3 have 12 significant bits, so their
// products with |k| < 2^12 are exact.
const P1_F32: f32 = 1.570_800_781_25; // 0x1.922p+0
const P2_F32: f32 = -4.453_584_551_811_218e-6; // -0x1.2aep-18
const P3_F32: f32 = -8.706_138_032_721_356e-10; // -0x1.deap-31
const P4_F32: f32 = 6.223_371_969_669_989e-14; // 0x1.184698p-44

// fdlibm k_sin.c: sin r ≈ r + S1·r³ + … + S6·r¹³ on [−π/4, π/4].
const S1_F64: f64 = -1.666_666_666_666_663_243_48e-1;
const S2_F64: f64 = 8.333_333_333_322_489_461_24e-3;
const S3_F64: f64 = -1.984_126_982_985_794_931_34e-4;
const S4_F64: f64 = 2.755_731_370_707_006_767_89e-6;
const S5_F64: f64 = -2.505_076_025_340_686_341_95e-8;
const S6_F64: f64 = 1.589_690_995_211_550_102_21e-10;
// fdlibm k_cos.c: cos r ≈ 1 − r²/2 + C1·r⁴ + … + C6·r¹² on [−π/4, π/4].
const C1_F64: f64 = 4.166_666_666_666_660_190_37e-2;
const C2_F64: f64 = -1.388_888_888_887_410_957_49e-3;
const C3_F64: f64 = 2.480_158_728_947_672_941_78e-5;
const C4_F64: f64 = -2.755_731_435_139_066_330_35e-7;
const C5_F64: f64 = 2.087_572_321_298_174_827_90e-9;
const C6_F64: f64 = -1.135_964_755_778_819_482_65e-11;

// FreeBSD k_sinf.c (|sin(x)/x − s(x)| < 2^-37.5) and k_cosf.c (|cos(x) − c(x)| < 2^-34.1),
// rounded to f32; their C0 = −0.4999999973 rounds to −1/2.
#[allow(clippy::cast_possible_truncation)]
mod coefficients_f32 {
    pub(super) const S1: f32 = -0.166_666_666_416_265_235_595_f64 as f32;
    pub(super) const S2: f32 = 0.008_333_329_385_889_463_175_6_f64 as f32;
    pub(super) const S3: f32 = -0.000_198_393_348_360_966_317_347_f64 as f32;
    pub(super) const S4: f32 = 0.000_002_718_311_493_989_821_906_4_f64 as f32;
    pub(super) const C1: f32 = 0.041_666_623_323_739_063_189_4_f64 as f32;
    pub(super) const C2: f32 = -0.001_388_676_377_460_992_946_92_f64 as f32;
    pub(super) const C3: f32 = 0.000_024_390_448_796_277_409_065_4_f64 as f32;
}
use coefficients_f32::{
    C1 as C1_F32, C2 as C2_F32, C3 as C3_F32, S1 as S1_F32, S2 as S2_F32, S3 as S3_F32,
    S4 as S4_F32,
};

/// `(sin x, cos x)` for `f64`.
#[inline(always)]
pub(crate) fn sin_cos_f64(x: f64) -> (f64, f64) {
    let ax = x.abs();
    if (TINY_F64..=BOUND_F64).contains(&ax) {
        fast_f64(x)
    } else {
        slow_f64(x)
    }
}

/// `(sin x, cos x)` for `f32`.
#[inline(always)]
pub(crate) fn sin_cos_f32(x: f32) -> (f32, f32) {
    let ax = x.abs();
    if (TINY_F32..=BOUND_F32).contains(&ax) {
        fast_f32(x)
    } else {
        slow_f32(x)
    }
}

#[cold]
#[inline(never)]
fn slow_f64(x: f64) -> (f64, f64) {
    if x.abs() < TINY_F64 {
        (x, 1.0)
    } else {
        libm::sincos(x)
    }
}

#[cold]
#[inline(never)]
fn slow_f32(x: f32) -> (f32, f32) {
    if x.abs() < TINY_F32 {
        (x, 1.0)
    } else {
        libm::sincosf(x)
    }
}

/// The reduction and the kernels of `f64`, written once for the scalar and the vector paths:
/// `$x` is the argument (a number or a register), `$k` makes a constant of that kind, and
/// `$add`, `$sub`, `$mul` are its operations and `$fma` its `a·b + c` (one rounding where the
/// build has FMA, two elsewhere, on every path alike). Gives `(shifted, sin r, cos r)`:
/// `k mod 4` is in the low bits of `shifted`. Every path runs these operations in this order,
/// which is why their results agree bit for bit.
macro_rules! reduce_and_evaluate_f64 {
    ($x:expr, $k:expr, $add:expr, $sub:expr, $mul:expr, $fma:expr) => {{
        let (x, k, add, sub, mul, fma) = ($x, $k, $add, $sub, $mul, $fma);
        // One rounding where the build has FMA: the integer nearest the exact x·(2/π).
        let shifted = fma(x, k(core::f64::consts::FRAC_2_PI), k(SHIFT_F64));
        let n = sub(shifted, k(SHIFT_F64));

        // x − n·P1, n·P2 are exact. Their difference is exact below 2^-20 (both lie on the
        // grid 2^-73); above, |x − n·P1| > |n·P2|, so Fast2Sum recovers its rounding error `e`.
        // Then |r| > 400·|n·P3| over the whole range, so the second Fast2Sum is valid too. `e`
        // goes into `r_lo` rather than `r`, off the critical path (|r_lo| stays below an ulp
        // of `r`).
        // Exact products: fusing them with their subtraction changes no bit, only the chain.
        let a = fma(n, k(-P1_F64), x);
        let b = mul(n, k(P2_F64));
        let c = mul(n, k(P3_F64));
        let s = fma(n, k(-P2_F64), a);
        let e = sub(sub(a, s), b);
        let r = sub(s, c);
        let r_lo = add(sub(sub(s, r), c), e);

        // The polynomials in Estrin's scheme, `fma(a, b, c) = a·b + c` fused where the build
        // has FMA: a shorter chain from the argument to the result. `z` is squared from `s`, a
        // step before `r = s − n·P3`: it only feeds terms of order r³ and r², which it changes by
        // |r·n·P3| < 4e-19, under 0.003 ulp of the result.
        let z = mul(s, s);
        let z2 = mul(z, z);
        let z4 = mul(z2, z2);
        let pair = |p: f64, q: f64| fma(z, k(q), k(p));
        let sin_poly = fma(
            z4,
            pair(S5_F64, S6_F64),
            fma(z2, pair(S3_F64, S4_F64), pair(S1_F64, S2_F64)),
        );
        let cos_poly = fma(
            z4,
            pair(C5_F64, C6_F64),
            fma(z2, pair(C3_F64, C4_F64), pair(C1_F64, C2_F64)),
        );
        let half_z = mul(k(0.5), z);
        let w = sub(k(1.0), half_z);
        let sin_r = add(r, fma(mul(r, z), sin_poly, mul(r_lo, w)));
        let cos_r = add(
            w,
            sub(
                fma(z2, cos_poly, sub(sub(k(1.0), w), half_z)),
                mul(r, r_lo),
            ),
        );
        (shifted, sin_r, cos_r)
    }};
}

/// [`reduce_and_evaluate_f64`] for `f32`.
macro_rules! reduce_and_evaluate_f32 {
    ($x:expr, $k:expr, $add:expr, $sub:expr, $mul:expr, $fma:expr) => {{
        let (x, k, add, sub, mul, fma) = ($x, $k, $add, $sub, $mul, $fma);
        // One rounding where the build has FMA: the integer nearest the exact x·(2/π).
        let shifted = fma(x, k(core::f32::consts::FRAC_2_PI), k(SHIFT_F32));
        let n = sub(shifted, k(SHIFT_F32));

        // x − n·P1, n·P2, n·P3 are exact. a − b is exact below 2^-5 (grid 2^-29), and above it
        // |a| > |b|: Fast2Sum. s − c has no such margin: TwoSum. |r| > 400·|n·P4|: Fast2Sum.
        // The errors go into `r_lo`, off the critical path.
        // Exact products: fusing them with their subtraction changes no bit, only the chain.
        let a = fma(n, k(-P1_F32), x);
        let b = mul(n, k(P2_F32));
        let c = mul(n, k(P3_F32));
        let d = mul(n, k(P4_F32));
        let s = fma(n, k(-P2_F32), a);
        let e1 = sub(sub(a, s), b);
        let t = fma(n, k(-P3_F32), s);
        let t_s = sub(t, s);
        let e2 = sub(sub(s, sub(t, t_s)), add(c, t_s));
        let r = sub(t, d);
        let r_lo = add(sub(sub(t, r), d), add(e1, e2));

        // `z` from `t`, a step before `r = t − n·P4`: a change under |r·n·P4| < 2e-10, 0.003
        // ulp of the result (as for f64).
        let z = mul(t, t);
        let z2 = mul(z, z);
        let pair = |p: f32, q: f32| fma(z, k(q), k(p));
        let sin_poly = fma(z2, pair(S3_F32, S4_F32), pair(S1_F32, S2_F32));
        let cos_poly = fma(z2, k(C3_F32), pair(C1_F32, C2_F32));
        let half_z = mul(k(0.5), z);
        let w = sub(k(1.0), half_z);
        let sin_r = add(r, fma(mul(r, z), sin_poly, mul(r_lo, w)));
        let cos_r = add(
            w,
            sub(
                fma(z2, cos_poly, sub(sub(k(1.0), w), half_z)),
                mul(r, r_lo),
            ),
        );
        (shifted, sin_r, cos_r)
    }};
}

/// `a·b + c`: one rounding where the build has FMA (as the vector paths, so that they agree
/// bit for bit), two elsewhere.
#[inline(always)]
fn fma_f64(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(all(target_arch = "x86_64", target_feature = "fma"))]
    {
        use core::arch::x86_64::{_mm_cvtsd_f64, _mm_fmadd_sd, _mm_set_sd};
        #[allow(unsafe_code)]
        // SAFETY: compiled only when the build enables FMA, the intrinsic's one requirement.
        unsafe {
            _mm_cvtsd_f64(_mm_fmadd_sd(_mm_set_sd(a), _mm_set_sd(b), _mm_set_sd(c)))
        }
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "fma")))]
    {
        a * b + c
    }
}

#[inline(always)]
fn fast_f64(x: f64) -> (f64, f64) {
    let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
        x,
        |c: f64| c,
        |a: f64, b: f64| a + b,
        |a: f64, b: f64| a - b,
        |a: f64, b: f64| a * b,
        fma_f64
    );
    #[allow(clippy::cast_possible_truncation)]
    let quadrant = shifted.to_bits() as u32;
    quadrant_f64(quadrant, sin_r, cos_r)
}

/// [`fma_f64`] for `f32`.
#[inline(always)]
fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    #[cfg(all(target_arch = "x86_64", target_feature = "fma"))]
    {
        use core::arch::x86_64::{_mm_cvtss_f32, _mm_fmadd_ss, _mm_set_ss};
        #[allow(unsafe_code)]
        // SAFETY: compiled only when the build enables FMA, the intrinsic's one requirement.
        unsafe {
            _mm_cvtss_f32(_mm_fmadd_ss(_mm_set_ss(a), _mm_set_ss(b), _mm_set_ss(c)))
        }
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "fma")))]
    {
        a * b + c
    }
}

#[inline(always)]
fn fast_f32(x: f32) -> (f32, f32) {
    let (shifted, sin_r, cos_r) = reduce_and_evaluate_f32!(
        x,
        |c: f32| c,
        |a: f32, b: f32| a + b,
        |a: f32, b: f32| a - b,
        |a: f32, b: f32| a * b,
        fma_f32
    );
    quadrant_f32(shifted.to_bits(), sin_r, cos_r)
}

/// `sin(x)` and `cos(x)` as combinations of `sin r` and `cos r` with coefficients 0 and ±1,
/// indexed by `k mod 4`: `sin(r + kπ/2) = T[k]·sin r + T[k + 3]·cos r` and
/// `cos(r + kπ/2) = T[k + 1]·sin r + T[k]·cos r`. The products and the sum are exact (one
/// term is ±0, the other is never 0 on the fast path), and no branch depends on `k`.
const QUADRANT_F64: [f64; 8] = [1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0];
/// [`QUADRANT_F64`] for `f32`.
const QUADRANT_F32: [f32; 8] = [1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0];

#[inline(always)]
fn quadrant_f64(k: u32, sin_r: f64, cos_r: f64) -> (f64, f64) {
    let k = (k & 3) as usize;
    let t = &QUADRANT_F64;
    (
        t[k] * sin_r + t[k + 3] * cos_r,
        t[k + 1] * sin_r + t[k] * cos_r,
    )
}

#[inline(always)]
fn quadrant_f32(k: u32, sin_r: f32, cos_r: f32) -> (f32, f32) {
    let k = (k & 3) as usize;
    let t = &QUADRANT_F32;
    (
        t[k] * sin_r + t[k + 3] * cos_r,
        t[k + 1] * sin_r + t[k] * cos_r,
    )
}

/// Sines and cosines of four `f64` arguments, each pair equal to [`sin_cos_f64`] of its
/// argument, bit for bit. With AVX2 and all four in the fast range, the four lanes are
/// computed at once in vector registers, the same operations in the same order as
/// [`sin_cos_f64`]; otherwise one by one.
#[inline(always)]
pub(crate) fn sin_cos_4_f64(x: [f64; 4]) -> ([f64; 4], [f64; 4]) {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    {
        #[allow(unsafe_code)]
        // SAFETY: this block is compiled only when the build enables AVX2 (the `cfg` above),
        // which is the one requirement of `lanes::in_fast_range` and `lanes::fast_4`.
        unsafe {
            if lanes::in_fast_range(x) {
                return lanes::fast_4(x);
            }
        }
    }
    #[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
    {
        #[allow(unsafe_code)]
        // SAFETY: SSE2, the one requirement of `pairs::in_fast_range` and `pairs::fast_2`, is
        // part of every x86-64 CPU and enabled in every x86-64 build.
        unsafe {
            if pairs::in_fast_range(x) {
                let ((s01, c01), (s23, c23)) =
                    (pairs::fast_2([x[0], x[1]]), pairs::fast_2([x[2], x[3]]));
                return (
                    [s01[0], s01[1], s23[0], s23[1]],
                    [c01[0], c01[1], c23[0], c23[1]],
                );
            }
        }
    }
    let (s0, c0) = sin_cos_f64(x[0]);
    let (s1, c1) = sin_cos_f64(x[1]);
    let (s2, c2) = sin_cos_f64(x[2]);
    let (s3, c3) = sin_cos_f64(x[3]);
    ([s0, s1, s2, s3], [c0, c1, c2, c3])
}

/// Sines and cosines of four `f32` arguments, each pair equal to [`sin_cos_f32`] of its
/// argument, bit for bit: on x86-64 with all four in the fast range, in the four lanes of an
/// SSE register; otherwise one by one.
#[inline(always)]
pub(crate) fn sin_cos_4_f32(x: [f32; 4]) -> ([f32; 4], [f32; 4]) {
    #[cfg(target_arch = "x86_64")]
    {
        #[allow(unsafe_code)]
        // SAFETY: SSE2, the one requirement of `quads::in_fast_range` and `quads::fast_4`, is
        // part of every x86-64 CPU and enabled in every x86-64 build.
        unsafe {
            if quads::in_fast_range(x) {
                return quads::fast_4(x);
            }
        }
    }
    let (s0, c0) = sin_cos_f32(x[0]);
    let (s1, c1) = sin_cos_f32(x[1]);
    let (s2, c2) = sin_cos_f32(x[2]);
    let (s3, c3) = sin_cos_f32(x[3]);
    ([s0, s1, s2, s3], [c0, c1, c2, c3])
}

/// [`fast_f64`] on four lanes of AVX2 registers. The functions are `unsafe` only because they
/// are `#[target_feature]` functions (as the crate's minimum Rust version requires); their
/// bodies are plain arithmetic on registers. They are `#[inline]` (here and in the SSE2
/// modules below) so that the generated code, in the user's crate, can inline them where its
/// build has the feature: otherwise each call crosses the crate as a real call, its arguments
/// and results through memory (random5's g took 56 ns that way, 38 ns inlined).
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
#[allow(unsafe_code)]
mod lanes {
    use super::{
        BOUND_F64, C1_F64, C2_F64, C3_F64, C4_F64, C5_F64, C6_F64, P1_F64, P2_F64, P3_F64, S1_F64,
        S2_F64, S3_F64, S4_F64, S5_F64, S6_F64, SHIFT_F64, TINY_F64,
    };
    use core::arch::x86_64::{
        __m256d, _mm256_add_epi64, _mm256_add_pd, _mm256_and_pd, _mm256_and_si256,
        _mm256_andnot_pd, _mm256_blendv_pd, _mm256_castpd256_pd128, _mm256_castpd_si256,
        _mm256_castsi256_pd, _mm256_cmp_pd, _mm256_cmpeq_epi64, _mm256_extractf128_pd,
        _mm256_movemask_pd, _mm256_mul_pd, _mm256_set1_epi64x, _mm256_set1_pd, _mm256_set_pd,
        _mm256_slli_epi64, _mm256_sub_pd, _mm256_xor_pd, _mm_cvtsd_f64, _mm_unpackhi_pd,
        _CMP_GE_OQ, _CMP_LE_OQ,
    };

    /// The four lanes of `v`.
    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn lanes(v: __m256d) -> [f64; 4] {
        let lo = _mm256_castpd256_pd128(v);
        let hi = _mm256_extractf128_pd::<1>(v);
        [
            _mm_cvtsd_f64(lo),
            _mm_cvtsd_f64(_mm_unpackhi_pd(lo, lo)),
            _mm_cvtsd_f64(hi),
            _mm_cvtsd_f64(_mm_unpackhi_pd(hi, hi)),
        ]
    }

    /// `a·b + c` on four lanes, fused where the build has FMA (as `super::fma_f64`).
    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn fma(a: __m256d, b: __m256d, c: __m256d) -> __m256d {
        #[cfg(target_feature = "fma")]
        return core::arch::x86_64::_mm256_fmadd_pd(a, b, c);
        #[cfg(not(target_feature = "fma"))]
        return _mm256_add_pd(_mm256_mul_pd(a, b), c);
    }

    /// Whether all four `|x|` lie in `[TINY_F64, BOUND_F64]` (a NaN does not): two vector
    /// comparisons and one mask, where four scalar tests take a dozen instructions and branches.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn in_fast_range(x: [f64; 4]) -> bool {
        let x = _mm256_set_pd(x[3], x[2], x[1], x[0]);
        let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
        let low = _mm256_cmp_pd::<_CMP_GE_OQ>(abs, _mm256_set1_pd(TINY_F64));
        let high = _mm256_cmp_pd::<_CMP_LE_OQ>(abs, _mm256_set1_pd(BOUND_F64));
        _mm256_movemask_pd(_mm256_and_pd(low, high)) == 0b1111
    }

    /// `(sin x, cos x)` of four arguments in the fast range: [`super::fast_f64`] lane by lane,
    /// the quadrant chosen by a swap (odd `k`) and two sign flips instead of the table.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn fast_4(x: [f64; 4]) -> ([f64; 4], [f64; 4]) {
        let x = _mm256_set_pd(x[3], x[2], x[1], x[0]);
        let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
            x,
            |c: f64| _mm256_set1_pd(c),
            |a, b| _mm256_add_pd(a, b),
            |a, b| _mm256_sub_pd(a, b),
            |a, b| _mm256_mul_pd(a, b),
            |a, b, c| fma(a, b, c)
        );

        // k mod 4 is in the low bits of `shifted`.
        let bits = _mm256_castpd_si256(shifted);
        let one = _mm256_set1_epi64x(1);
        let two = _mm256_set1_epi64x(2);
        let odd = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(bits, one), one));
        let sin_k = _mm256_blendv_pd(sin_r, cos_r, odd);
        let cos_k = _mm256_blendv_pd(cos_r, sin_r, odd);
        let sin_sign = _mm256_slli_epi64::<62>(_mm256_and_si256(bits, two));
        let cos_sign = _mm256_slli_epi64::<62>(_mm256_and_si256(_mm256_add_epi64(bits, one), two));
        (
            lanes(_mm256_xor_pd(sin_k, _mm256_castsi256_pd(sin_sign))),
            lanes(_mm256_xor_pd(cos_k, _mm256_castsi256_pd(cos_sign))),
        )
    }
}

/// [`fast_f64`] on the two lanes of SSE2 registers, which every x86-64 CPU has: the path of
/// builds without AVX2 (the default `x86_64` target). The same operations as [`lanes`], on half
/// the width, with SSE2's bitwise masks in place of AVX's blend.
#[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
#[allow(unsafe_code)]
mod pairs {
    use super::{
        BOUND_F64, C1_F64, C2_F64, C3_F64, C4_F64, C5_F64, C6_F64, P1_F64, P2_F64, P3_F64, S1_F64,
        S2_F64, S3_F64, S4_F64, S5_F64, S6_F64, SHIFT_F64, TINY_F64,
    };
    use core::arch::x86_64::{
        __m128d, _mm_add_epi64, _mm_add_pd, _mm_and_pd, _mm_and_si128, _mm_andnot_pd,
        _mm_castpd_si128, _mm_castsi128_pd, _mm_cmpge_pd, _mm_cmple_pd, _mm_cvtsd_f64,
        _mm_movemask_pd, _mm_mul_pd, _mm_or_pd, _mm_set1_epi64x, _mm_set1_pd, _mm_set_pd,
        _mm_shuffle_epi32, _mm_slli_epi64, _mm_srai_epi32, _mm_sub_pd, _mm_unpackhi_pd, _mm_xor_pd,
    };

    /// The two lanes of `v`.
    #[inline]
    #[target_feature(enable = "sse2")]
    unsafe fn lanes(v: __m128d) -> [f64; 2] {
        [_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))]
    }

    /// `a·b + c` on two lanes, fused where the build has FMA (as `super::fma_f64`).
    #[inline]
    #[target_feature(enable = "sse2")]
    unsafe fn fma(a: __m128d, b: __m128d, c: __m128d) -> __m128d {
        #[cfg(target_feature = "fma")]
        return core::arch::x86_64::_mm_fmadd_pd(a, b, c);
        #[cfg(not(target_feature = "fma"))]
        return _mm_add_pd(_mm_mul_pd(a, b), c);
    }

    /// Whether all four `|x|` lie in `[TINY_F64, BOUND_F64]` (a NaN does not), two lanes a
    /// comparison.
    #[inline]
    #[target_feature(enable = "sse2")]
    pub(super) unsafe fn in_fast_range(x: [f64; 4]) -> bool {
        let inside = |a: f64, b: f64| {
            let abs = _mm_andnot_pd(_mm_set1_pd(-0.0), _mm_set_pd(b, a));
            let low = _mm_cmpge_pd(abs, _mm_set1_pd(TINY_F64));
            let high = _mm_cmple_pd(abs, _mm_set1_pd(BOUND_F64));
            _mm_and_pd(low, high)
        };
        _mm_movemask_pd(_mm_and_pd(inside(x[0], x[1]), inside(x[2], x[3]))) == 0b11
    }

    /// `(sin x, cos x)` of two arguments in the fast range.
    #[inline]
    #[target_feature(enable = "sse2")]
    pub(super) unsafe fn fast_2(x: [f64; 2]) -> ([f64; 2], [f64; 2]) {
        let x = _mm_set_pd(x[1], x[0]);
        let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
            x,
            |c: f64| _mm_set1_pd(c),
            |a, b| _mm_add_pd(a, b),
            |a, b| _mm_sub_pd(a, b),
            |a, b| _mm_mul_pd(a, b),
            |a, b, c| fma(a, b, c)
        );

        // k mod 4 is in the low bits of `shifted`. Odd k swaps sine and cosine: the low bit,
        // moved to the top and spread by an arithmetic shift, masks each 64-bit lane whole.
        let bits = _mm_castpd_si128(shifted);
        let one = _mm_set1_epi64x(1);
        let two = _mm_set1_epi64x(2);
        let top = _mm_srai_epi32::<31>(_mm_slli_epi64::<63>(bits));
        let odd = _mm_castsi128_pd(_mm_shuffle_epi32::<0b11_11_01_01>(top));
        let pick = |m: __m128d, yes: __m128d, no: __m128d| {
            _mm_or_pd(_mm_and_pd(m, yes), _mm_andnot_pd(m, no))
        };
        let sin_k = pick(odd, cos_r, sin_r);
        let cos_k = pick(odd, sin_r, cos_r);
        let sin_sign = _mm_slli_epi64::<62>(_mm_and_si128(bits, two));
        let cos_sign = _mm_slli_epi64::<62>(_mm_and_si128(_mm_add_epi64(bits, one), two));
        (
            lanes(_mm_xor_pd(sin_k, _mm_castsi128_pd(sin_sign))),
            lanes(_mm_xor_pd(cos_k, _mm_castsi128_pd(cos_sign))),
        )
    }
}

/// [`fast_f32`] on the four lanes of SSE registers, which every x86-64 CPU has.
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
mod quads {
    use super::{
        BOUND_F32, C1_F32, C2_F32, C3_F32, P1_F32, P2_F32, P3_F32, P4_F32, S1_F32, S2_F32, S3_F32,
        S4_F32, SHIFT_F32, TINY_F32,
    };
    use core::arch::x86_64::{
        __m128, _mm_add_epi32, _mm_add_ps, _mm_and_ps, _mm_and_si128, _mm_andnot_ps,
        _mm_castps_si128, _mm_castsi128_ps, _mm_cmpeq_epi32, _mm_cmpge_ps, _mm_cmple_ps,
        _mm_movemask_ps, _mm_mul_ps, _mm_or_ps, _mm_set1_epi32, _mm_set1_ps, _mm_slli_epi32,
        _mm_storeu_ps, _mm_sub_ps, _mm_xor_ps,
    };

    /// The four lanes of `v`.
    #[inline]
    #[target_feature(enable = "sse2")]
    unsafe fn lanes(v: __m128) -> [f32; 4] {
        let mut out = [0.0; 4];
        _mm_storeu_ps(out.as_mut_ptr(), v);
        out
    }

    /// `a·b + c` on four lanes, fused where the build has FMA (as `super::fma_f32`).
    #[inline]
    #[target_feature(enable = "sse2")]
    unsafe fn fma(a: __m128, b: __m128, c: __m128) -> __m128 {
        #[cfg(target_feature = "fma")]
        return core::arch::x86_64::_mm_fmadd_ps(a, b, c);
        #[cfg(not(target_feature = "fma"))]
        return _mm_add_ps(_mm_mul_ps(a, b), c);
    }

    /// Whether all four `|x|` lie in `[TINY_F32, BOUND_F32]` (a NaN does not).
    #[inline]
    #[target_feature(enable = "sse2")]
    pub(super) unsafe fn in_fast_range(x: [f32; 4]) -> bool {
        let x = core::arch::x86_64::_mm_set_ps(x[3], x[2], x[1], x[0]);
        let abs = _mm_andnot_ps(_mm_set1_ps(-0.0), x);
        let low = _mm_cmpge_ps(abs, _mm_set1_ps(TINY_F32));
        let high = _mm_cmple_ps(abs, _mm_set1_ps(BOUND_F32));
        _mm_movemask_ps(_mm_and_ps(low, high)) == 0b1111
    }

    /// `(sin x, cos x)` of four arguments in the fast range.
    #[inline]
    #[target_feature(enable = "sse2")]
    pub(super) unsafe fn fast_4(x: [f32; 4]) -> ([f32; 4], [f32; 4]) {
        let x = core::arch::x86_64::_mm_set_ps(x[3], x[2], x[1], x[0]);
        let (shifted, sin_r, cos_r) = reduce_and_evaluate_f32!(
            x,
            |c: f32| _mm_set1_ps(c),
            |a, b| _mm_add_ps(a, b),
            |a, b| _mm_sub_ps(a, b),
            |a, b| _mm_mul_ps(a, b),
            |a, b, c| fma(a, b, c)
        );

        // k mod 4 is in the low bits of `shifted`: odd k swaps sine and cosine.
        let bits = _mm_castps_si128(shifted);
        let one = _mm_set1_epi32(1);
        let two = _mm_set1_epi32(2);
        let odd = _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(bits, one), one));
        let pick = |m: __m128, yes: __m128, no: __m128| {
            _mm_or_ps(_mm_and_ps(m, yes), _mm_andnot_ps(m, no))
        };
        let sin_k = pick(odd, cos_r, sin_r);
        let cos_k = pick(odd, sin_r, cos_r);
        let sin_sign = _mm_slli_epi32::<30>(_mm_and_si128(bits, two));
        let cos_sign = _mm_slli_epi32::<30>(_mm_and_si128(_mm_add_epi32(bits, one), two));
        (
            lanes(_mm_xor_ps(sin_k, _mm_castsi128_ps(sin_sign))),
            lanes(_mm_xor_ps(cos_k, _mm_castsi128_ps(cos_sign))),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Significant bits of a finite, nonzero `f64` (its `f32`s are exactly `f64`s).
    fn significant_bits(x: f64) -> u32 {
        let mantissa = (x.to_bits() & ((1 << 52) - 1)) | (1 << 52);
        53 - mantissa.trailing_zeros()
    }

    #[test]
    fn parts_of_half_pi_are_the_analysed_ones() {
        // The bit patterns the exhaustive analysis used.
        assert_eq!(P1_F64.to_bits(), 0x3FF9_21FB_5444_0000);
        assert_eq!(P2_F64.to_bits(), 0x3D86_8C23_4C4C_0000);
        assert_eq!(P3_F64.to_bits(), 0x3B29_8A2E_0370_7345);
        assert_eq!(P1_F32.to_bits(), 0x3FC9_1000);
        assert_eq!(P2_F32.to_bits(), 0xB695_7000);
        assert_eq!(P3_F32.to_bits(), 0xB06F_5000);
        assert_eq!(P4_F32.to_bits(), 0x298C_234C);
        // k·P is exact for |k| < 2^16 (f64) and 2^12 (f32).
        assert!(significant_bits(P1_F64) + 16 <= 53 && significant_bits(P2_F64) + 16 <= 53);
        for p in [P1_F32, P2_F32, P3_F32] {
            assert!(significant_bits(f64::from(p)) + 12 <= 24);
        }
        // The largest k of the fast range stays below those limits.
        assert!((BOUND_F64 * core::f64::consts::FRAC_2_PI).round() < 65_536.0);
        assert!((BOUND_F32 * core::f32::consts::FRAC_2_PI).round() < 4_096.0);
        // And the sum is π/2 to the working precision.
        assert_eq!(P1_F64 + P2_F64, core::f64::consts::FRAC_PI_2);
        assert_eq!(P1_F32 + P2_F32 + P3_F32, core::f32::consts::FRAC_PI_2);
    }

    #[test]
    fn thresholds_are_powers_of_two() {
        assert_eq!(TINY_F64, 2f64.powi(-27));
        assert_eq!(TINY_F32, 2f32.powi(-12));
        assert_eq!(SHIFT_F64, 1.5 * 2f64.powi(52));
        assert_eq!(SHIFT_F32, 1.5 * 2f32.powi(23));
    }
}
