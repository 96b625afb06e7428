//! `super::scalar::fast_f32` on the four lanes of SSE registers, which every x86-64 CPU has.

use super::kernels::{C1_F32, C2_F32, C3_F32, S1_F32, S2_F32, S3_F32, S4_F32};
use super::reduction::{BOUND_F32, P1_F32, P2_F32, P3_F32, P4_F32, SHIFT_F32, TINY_F32};
use core::arch::x86_64::{
    __m128, _mm_add_epi32, _mm_add_ps, _mm_and_ps, _mm_and_si128, _mm_andnot_ps, _mm_castps_si128,
    _mm_castsi128_ps, _mm_cmpeq_epi32, _mm_cmpge_ps, _mm_cmple_ps, _mm_movemask_ps, _mm_mul_ps,
    _mm_or_ps, _mm_set1_epi32, _mm_set1_ps, _mm_slli_epi32, _mm_storeu_ps, _mm_sub_ps, _mm_xor_ps,
};

/// The four lanes of `v`.
#[inline]
#[target_feature(enable = "sse2")]
unsafe fn lanes(v: __m128) -> [f32; 4] {
    let mut out = [0.0; 4];
    _mm_storeu_ps(out.as_mut_ptr(), v);
    out
}

/// `a·b + c` on four lanes, fused where the build has FMA (as `super::scalar::fma_f32`).
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
    _mm_movemask_ps(inside(x)) == 0b1111
}

/// [`in_fast_range`] of eight arguments, with one mask.
#[inline]
#[target_feature(enable = "sse2")]
pub(super) unsafe fn in_fast_range_8(lo: [f32; 4], hi: [f32; 4]) -> bool {
    _mm_movemask_ps(_mm_and_ps(inside(lo), inside(hi))) == 0b1111
}

/// All ones in the lanes whose `|x|` lies in `[TINY_F32, BOUND_F32]`.
#[inline]
#[target_feature(enable = "sse2")]
unsafe fn inside(x: [f32; 4]) -> __m128 {
    let x = core::arch::x86_64::_mm_set_ps(x[3], x[2], x[1], x[0]);
    let abs = _mm_andnot_ps(_mm_set1_ps(-0.0), x);
    let low = _mm_cmpge_ps(abs, _mm_set1_ps(TINY_F32));
    let high = _mm_cmple_ps(abs, _mm_set1_ps(BOUND_F32));
    _mm_and_ps(low, high)
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
    let pick =
        |m: __m128, yes: __m128, no: __m128| _mm_or_ps(_mm_and_ps(m, yes), _mm_andnot_ps(m, no));
    let sin_k = pick(odd, cos_r, sin_r);
    let cos_k = pick(odd, sin_r, cos_r);
    let sin_sign = _mm_slli_epi32::<30>(_mm_and_si128(bits, two));
    let cos_sign = _mm_slli_epi32::<30>(_mm_and_si128(_mm_add_epi32(bits, one), two));
    (
        lanes(_mm_xor_ps(sin_k, _mm_castsi128_ps(sin_sign))),
        lanes(_mm_xor_ps(cos_k, _mm_castsi128_ps(cos_sign))),
    )
}

/// [`in_fast_range`] of a register, for the lane types (`crate::lanes`). Through the array
/// form, which the compiler folds away, so that the scalar path's code stays as it was.
#[inline]
#[target_feature(enable = "sse2")]
pub(crate) unsafe fn in_fast_range_v(x: __m128) -> bool {
    in_fast_range(lanes(x))
}

/// [`fast_4`] of a register, for the lane types.
#[inline]
#[target_feature(enable = "sse2")]
pub(crate) unsafe fn fast_4_v(x: __m128) -> (__m128, __m128) {
    let (sin, cos) = fast_4(lanes(x));
    let load = |v: [f32; 4]| core::arch::x86_64::_mm_set_ps(v[3], v[2], v[1], v[0]);
    (load(sin), load(cos))
}
