//! `super::scalar::fast_f64` on the two lanes of SSE2 registers, which every x86-64 CPU has:
//! the path of builds without AVX2 (the default `x86_64` target). The same operations as
//! `super::avx2_f64`, on half the width, with SSE2's bitwise masks in place of AVX's blend.

use super::kernels::{
    C1_F64, C2_F64, C3_F64, C4_F64, C5_F64, C6_F64, S1_F64, S2_F64, S3_F64, S4_F64, S5_F64, S6_F64,
};
use super::reduction::{BOUND_F64, P1_F64, P2_F64, P3_F64, SHIFT_F64};
use core::arch::x86_64::{
    __m128d, _mm_and_pd, _mm_andnot_pd, _mm_castpd_si128, _mm_castsi128_pd, _mm_cmple_pd,
    _mm_cvtsd_f64, _mm_movemask_pd, _mm_mul_pd, _mm_or_pd, _mm_set1_pd, _mm_set_pd,
    _mm_shuffle_epi32, _mm_slli_epi64, _mm_srai_epi32, _mm_sub_pd, _mm_unpackhi_pd, _mm_xor_pd,
};

/// The two lanes of `v`.
#[inline]
#[target_feature(enable = "sse2")]
unsafe fn lanes(v: __m128d) -> [f64; 2] {
    [_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))]
}

/// `a·b + c` on two lanes, fused where the build has FMA (as `super::scalar::fma_f64`).
#[inline]
#[target_feature(enable = "sse2")]
unsafe fn fma(a: __m128d, b: __m128d, c: __m128d) -> __m128d {
    #[cfg(target_feature = "fma")]
    return core::arch::x86_64::_mm_fmadd_pd(a, b, c);
    #[cfg(not(target_feature = "fma"))]
    return core::arch::x86_64::_mm_add_pd(_mm_mul_pd(a, b), c);
}

/// Whether all four `|x|` are at most `BOUND_F64` (a NaN is not), two lanes a comparison.
#[inline]
#[target_feature(enable = "sse2")]
pub(super) unsafe fn in_fast_range(x: [f64; 4]) -> bool {
    let inside = |a: f64, b: f64| {
        let abs = _mm_andnot_pd(_mm_set1_pd(-0.0), _mm_set_pd(b, a));
        _mm_cmple_pd(abs, _mm_set1_pd(BOUND_F64))
    };
    _mm_movemask_pd(_mm_and_pd(inside(x[0], x[1]), inside(x[2], x[3]))) == 0b11
}

/// `(sin x, cos x)` of two arguments in the fast range, on `|x|`.
#[inline]
#[target_feature(enable = "sse2")]
pub(super) unsafe fn fast_2(x: [f64; 2]) -> ([f64; 2], [f64; 2]) {
    let x = _mm_set_pd(x[1], x[0]);
    let sign_bit = _mm_set1_pd(-0.0);
    let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
        _mm_andnot_pd(sign_bit, x),
        |c: f64| _mm_set1_pd(c),
        |a, b| _mm_sub_pd(a, b),
        |a, b| _mm_mul_pd(a, b),
        |a, b, c| fma(a, b, c)
    );

    // k mod 4 is in the low bits of `shifted`. Odd k swaps sine and cosine: the low bit,
    // moved to the top and spread by an arithmetic shift, masks each 64-bit lane whole. Bit 1
    // moved to the top is the sine's sign, and the cosine's is the exclusive or of the two.
    let bits = _mm_castpd_si128(shifted);
    let low = _mm_slli_epi64::<63>(bits);
    let odd = _mm_castsi128_pd(_mm_shuffle_epi32::<0b11_11_01_01>(_mm_srai_epi32::<31>(
        low,
    )));
    let pick =
        |m: __m128d, yes: __m128d, no: __m128d| _mm_or_pd(_mm_and_pd(m, yes), _mm_andnot_pd(m, no));
    let sin_k = pick(odd, cos_r, sin_r);
    let cos_k = pick(odd, sin_r, cos_r);
    let half = _mm_and_pd(_mm_castsi128_pd(_mm_slli_epi64::<62>(bits)), sign_bit);
    let sin_sign = _mm_xor_pd(half, _mm_and_pd(x, sign_bit));
    let cos_sign = _mm_xor_pd(half, _mm_castsi128_pd(low));
    (
        lanes(_mm_xor_pd(sin_k, sin_sign)),
        lanes(_mm_xor_pd(cos_k, cos_sign)),
    )
}

/// Whether both lanes of a register are in the fast range, for the lane types
/// (`crate::lanes`).
#[inline]
#[target_feature(enable = "sse2")]
pub(crate) unsafe fn in_fast_range_v(x: __m128d) -> bool {
    let [a, b] = lanes(x);
    in_fast_range([a, b, a, b])
}

/// [`fast_2`] of a register, for the lane types. Through the array form, which the compiler
/// folds away, so that the scalar path's code stays as it was.
#[inline]
#[target_feature(enable = "sse2")]
pub(crate) unsafe fn fast_2_v(x: __m128d) -> (__m128d, __m128d) {
    let (sin, cos) = fast_2(lanes(x));
    (_mm_set_pd(sin[1], sin[0]), _mm_set_pd(cos[1], cos[0]))
}
