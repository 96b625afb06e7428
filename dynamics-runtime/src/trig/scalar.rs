//! One argument at a time: the fast path (reduction, kernels, a branch-free choice of
//! quadrant), and `libm` outside the fast range.

use super::kernels::{
    C1_F32, C1_F64, C2_F32, C2_F64, C3_F32, C3_F64, C4_F64, C5_F64, C6_F64, S1_F32, S1_F64, S2_F32,
    S2_F64, S3_F32, S3_F64, S4_F32, S4_F64, S5_F64, S6_F64,
};
use super::reduction::{
    BOUND_F32, BOUND_F64, P1_F32, P1_F64, P2_F32, P2_F64, P3_F32, P3_F64, P4_F32, SHIFT_F32,
    SHIFT_F64, TINY_F32,
};

/// `(sin x, cos x)` for `f64`.
#[inline(always)]
pub(crate) fn sin_cos_f64(x: f64) -> (f64, f64) {
    if x.abs() <= BOUND_F64 {
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

/// Beyond the fast range, `±∞` and NaN (NaN in, NaN out).
#[cold]
#[inline(never)]
fn slow_f64(x: f64) -> (f64, f64) {
    libm::sincos(x)
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

/// The fast path on `|x|`, the sign of `x` put back on the sine: `sin_cos(-x)` is
/// `(-sin x, cos x)` bit for bit, and `sin(-0) = -0` without a test.
#[inline(always)]
fn fast_f64(x: f64) -> (f64, f64) {
    let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
        x.abs(),
        |c: f64| c,
        |a: f64, b: f64| a - b,
        |a: f64, b: f64| a * b,
        fma_f64
    );
    // k mod 4 is in the low bits of `shifted`: odd k swaps the two, bit 1 is the sine's sign
    // and bit 0 xor bit 1 the cosine's (as the vector paths' masks).
    let k = shifted.to_bits();
    let (sin, cos) = if k & 1 == 0 {
        (sin_r, cos_r)
    } else {
        (cos_r, sin_r)
    };
    let sin_sign = (k & 2) << 62 ^ (x.to_bits() & (1 << 63));
    let cos_sign = ((k ^ (k >> 1)) & 1) << 63;
    (
        f64::from_bits(sin.to_bits() ^ sin_sign),
        f64::from_bits(cos.to_bits() ^ cos_sign),
    )
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

/// `sin(x)` and `cos(x)` of `f32` as combinations of `sin r` and `cos r` with coefficients 0
/// and ±1, indexed by `k mod 4`: `sin(r + kπ/2) = T[k]·sin r + T[k + 3]·cos r` and
/// `cos(r + kπ/2) = T[k + 1]·sin r + T[k]·cos r`. The products and the sum are exact (one
/// term is ±0, the other is never 0 on the fast path), and no branch depends on `k`.
const QUADRANT_F32: [f32; 8] = [1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0];

#[inline(always)]
fn quadrant_f32(k: u32, sin_r: f32, cos_r: f32) -> (f32, f32) {
    let k = (k & 3) as usize;
    let t = &QUADRANT_F32;
    (
        t[k] * sin_r + t[k + 3] * cos_r,
        t[k + 1] * sin_r + t[k] * cos_r,
    )
}
