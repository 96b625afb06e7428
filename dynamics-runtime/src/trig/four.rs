//! Four or eight arguments at once (`Real::sin_cos_4`, `Real::sin_cos_8`, which generated code
//! calls for groups of up to four and five to eight joints): in vector lanes on x86-64 when all
//! of them are in the fast range, else one by one.

#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
use super::avx2_f64;
use super::scalar::{sin_cos_f32, sin_cos_f64};
#[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
use super::sse2_f64;
#[cfg(target_arch = "x86_64")]
use super::sse_f32;

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
        // which is the one requirement of `avx2_f64::in_fast_range` and `avx2_f64::fast_4`.
        unsafe {
            if avx2_f64::in_fast_range(x) {
                return avx2_f64::fast_4(x);
            }
        }
    }
    #[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
    {
        #[allow(unsafe_code)]
        // SAFETY: SSE2, the one requirement of `sse2_f64::in_fast_range` and `sse2_f64::fast_2`, is
        // part of every x86-64 CPU and enabled in every x86-64 build.
        unsafe {
            if sse2_f64::in_fast_range(x) {
                let ((s01, c01), (s23, c23)) = (
                    sse2_f64::fast_2([x[0], x[1]]),
                    sse2_f64::fast_2([x[2], x[3]]),
                );
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
        // SAFETY: SSE2, the one requirement of `sse_f32::in_fast_range` and `sse_f32::fast_4`, is
        // part of every x86-64 CPU and enabled in every x86-64 build.
        unsafe {
            if sse_f32::in_fast_range(x) {
                return sse_f32::fast_4(x);
            }
        }
    }
    let (s0, c0) = sin_cos_f32(x[0]);
    let (s1, c1) = sin_cos_f32(x[1]);
    let (s2, c2) = sin_cos_f32(x[2]);
    let (s3, c3) = sin_cos_f32(x[3]);
    ([s0, s1, s2, s3], [c0, c1, c2, c3])
}

/// The eight values of two groups of four.
#[inline(always)]
fn join<T: Copy>(a: [T; 4], b: [T; 4]) -> [T; 8] {
    [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]
}

/// Sines and cosines of eight `f64` arguments, each pair equal to [`sin_cos_f64`] of its
/// argument, bit for bit: the lanes of two [`sin_cos_4_f64`] with one range test for all
/// eight, so that a robot of five to eight joints takes one branch and both vectors are in
/// flight at once.
#[inline(always)]
pub(crate) fn sin_cos_8_f64(x: [f64; 8]) -> ([f64; 8], [f64; 8]) {
    let lo = [x[0], x[1], x[2], x[3]];
    let hi = [x[4], x[5], x[6], x[7]];
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    {
        #[allow(unsafe_code)]
        // SAFETY: this block is compiled only when the build enables AVX2 (the `cfg` above),
        // which is the one requirement of `avx2_f64::in_fast_range_8` and `avx2_f64::fast_4`.
        unsafe {
            if avx2_f64::in_fast_range_8(lo, hi) {
                let ((s0, c0), (s1, c1)) = (avx2_f64::fast_4(lo), avx2_f64::fast_4(hi));
                return (join(s0, s1), join(c0, c1));
            }
        }
    }
    let ((s0, c0), (s1, c1)) = (sin_cos_4_f64(lo), sin_cos_4_f64(hi));
    (join(s0, s1), join(c0, c1))
}

/// Sines and cosines of eight `f32` arguments, each pair equal to [`sin_cos_f32`] of its
/// argument, bit for bit: the lanes of two [`sin_cos_4_f32`] with one range test for all
/// eight.
#[inline(always)]
pub(crate) fn sin_cos_8_f32(x: [f32; 8]) -> ([f32; 8], [f32; 8]) {
    let lo = [x[0], x[1], x[2], x[3]];
    let hi = [x[4], x[5], x[6], x[7]];
    #[cfg(target_arch = "x86_64")]
    {
        #[allow(unsafe_code)]
        // SAFETY: SSE2, the one requirement of `sse_f32::in_fast_range_8` and `sse_f32::fast_4`,
        // is part of every x86-64 CPU and enabled in every x86-64 build.
        unsafe {
            if sse_f32::in_fast_range_8(lo, hi) {
                let ((s0, c0), (s1, c1)) = (sse_f32::fast_4(lo), sse_f32::fast_4(hi));
                return (join(s0, s1), join(c0, c1));
            }
        }
    }
    let ((s0, c0), (s1, c1)) = (sin_cos_4_f32(lo), sin_cos_4_f32(hi));
    (join(s0, s1), join(c0, c1))
}
