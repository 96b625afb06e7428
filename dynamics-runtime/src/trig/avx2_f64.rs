//! `super::scalar::fast_f64` on four lanes of AVX2 registers. The functions are `unsafe` only
//! because they are `#[target_feature]` functions (as the crate's minimum Rust version
//! requires); their bodies are plain arithmetic on registers. They are `#[inline]` (here and in
//! the SSE modules) so that the generated code, in the user's crate, can inline them where its
//! build has the feature: otherwise each call crosses the crate as a real call, its arguments
//! and results through memory, which costs more than the sines and cosines themselves save.

use super::kernels::{
    C1_F64, C2_F64, C3_F64, C4_F64, C5_F64, C6_F64, S1_F64, S2_F64, S3_F64, S4_F64, S5_F64, S6_F64,
};
use super::reduction::{BOUND_F64, P1_F64, P2_F64, P3_F64, SHIFT_F64};
use core::arch::x86_64::{
    __m256d, _mm256_and_pd, _mm256_andnot_pd, _mm256_blendv_pd, _mm256_castpd256_pd128,
    _mm256_castpd_si256, _mm256_castsi256_pd, _mm256_cmp_pd, _mm256_extractf128_pd,
    _mm256_movemask_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_slli_epi64, _mm256_sub_pd,
    _mm256_xor_pd, _mm_cvtsd_f64, _mm_unpackhi_pd, _CMP_LE_OQ,
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

/// `a·b + c` on four lanes, fused where the build has FMA (as `super::scalar::fma_f64`).
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn fma(a: __m256d, b: __m256d, c: __m256d) -> __m256d {
    #[cfg(target_feature = "fma")]
    return core::arch::x86_64::_mm256_fmadd_pd(a, b, c);
    #[cfg(not(target_feature = "fma"))]
    return core::arch::x86_64::_mm256_add_pd(_mm256_mul_pd(a, b), c);
}

/// The four arguments in one register. On a build with AVX-512 each half goes through an empty
/// `asm!` that LLVM cannot see into: otherwise it gathers arguments read from scattered
/// elements of one array (random5's `q[1]`, `q[3]`, `q[4]`, `q[5]`) with a masked 512-bit load
/// and a 512-bit permute, and on Intel's AVX-512 cores those two instructions slow down the
/// scalar code after them (`docs/performance.md`). A half of two lanes is at most a 128-bit
/// load or two.
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn load(x: [f64; 4]) -> __m256d {
    #[cfg(target_feature = "avx512f")]
    return core::arch::x86_64::_mm256_set_m128d(
        opaque(core::arch::x86_64::_mm_set_pd(x[3], x[2])),
        opaque(core::arch::x86_64::_mm_set_pd(x[1], x[0])),
    );
    #[cfg(not(target_feature = "avx512f"))]
    return core::arch::x86_64::_mm256_set_pd(x[3], x[2], x[1], x[0]);
}

/// `v` unchanged, through an empty `asm!` (no instruction, no memory, no flags): the compiler
/// no longer knows where it came from, so it cannot merge the loads that built it with others.
#[cfg(target_feature = "avx512f")]
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn opaque(mut v: core::arch::x86_64::__m128d) -> core::arch::x86_64::__m128d {
    core::arch::asm!("/* {0} */", inout(xmm_reg) v, options(pure, nomem, nostack, preserves_flags));
    v
}

/// Whether all four `|x|` are at most `BOUND_F64` (a NaN is not): one vector comparison and
/// one mask, where four scalar tests take a dozen instructions and branches.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) unsafe fn in_fast_range(x: [f64; 4]) -> bool {
    in_fast_range_v(load(x))
}

/// [`in_fast_range`] of eight arguments, with one mask.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) unsafe fn in_fast_range_8(lo: [f64; 4], hi: [f64; 4]) -> bool {
    _mm256_movemask_pd(_mm256_and_pd(inside(load(lo)), inside(load(hi)))) == 0b1111
}

/// All ones in the lanes whose `|x|` is at most `BOUND_F64`.
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn inside(x: __m256d) -> __m256d {
    let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
    _mm256_cmp_pd::<_CMP_LE_OQ>(abs, _mm256_set1_pd(BOUND_F64))
}

/// `(sin x, cos x)` of four arguments in the fast range: `super::scalar::fast_f64` lane by lane.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) unsafe fn fast_4(x: [f64; 4]) -> ([f64; 4], [f64; 4]) {
    let (sin, cos) = fast_4_v(load(x));
    (lanes(sin), lanes(cos))
}

/// [`in_fast_range`] of a register, for the lane types (`crate::lanes`).
#[inline]
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn in_fast_range_v(x: __m256d) -> bool {
    _mm256_movemask_pd(inside(x)) == 0b1111
}

/// [`fast_4`] of a register, for the lane types: on `|x|`, the quadrant chosen by a swap (odd
/// `k`) and two sign flips.
#[inline]
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn fast_4_v(x: __m256d) -> (__m256d, __m256d) {
    let sign_bit = _mm256_set1_pd(-0.0);
    let (shifted, sin_r, cos_r) = reduce_and_evaluate_f64!(
        _mm256_andnot_pd(sign_bit, x),
        |c: f64| _mm256_set1_pd(c),
        |a, b| _mm256_sub_pd(a, b),
        |a, b| _mm256_mul_pd(a, b),
        |a, b, c| fma(a, b, c)
    );

    // k mod 4 is in the low bits of `shifted`: bit 0 moved to the top selects (blendv reads
    // the top bit alone), bit 1 moved to the top is the sine's sign, and the cosine's is their
    // exclusive or.
    let bits = _mm256_castpd_si256(shifted);
    let odd = _mm256_castsi256_pd(_mm256_slli_epi64::<63>(bits));
    let half = _mm256_and_pd(_mm256_castsi256_pd(_mm256_slli_epi64::<62>(bits)), sign_bit);
    let sin_k = _mm256_blendv_pd(sin_r, cos_r, odd);
    let cos_k = _mm256_blendv_pd(cos_r, sin_r, odd);
    let sin_sign = _mm256_xor_pd(half, _mm256_and_pd(x, sign_bit));
    (
        _mm256_xor_pd(sin_k, sin_sign),
        _mm256_xor_pd(cos_k, _mm256_xor_pd(half, odd)),
    )
}
