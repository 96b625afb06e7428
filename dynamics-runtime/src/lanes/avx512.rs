//! The AVX-512 backend of `F64x8`: one 512-bit register, each operation one instruction on all
//! eight lanes, the same IEEE operation as the scalar's on each. Comparisons give a mask
//! register rather than a vector, so `sign` and the tests are written here rather than by the
//! SSE/AVX macro of `x86.rs`; sines and cosines run the AVX2 kernels on each half.
//!
//! Behind the `avx512` feature: its intrinsics are stable since Rust 1.89, later than the
//! crate's minimum version.
//!
//! SAFETY (every `unsafe` block of this file): the intrinsics require AVX-512F (and the AVX2
//! kernels AVX2), which the build enables wherever this module is compiled (its `cfg` in
//! `mod.rs`). Loads and stores go through arrays of exactly the register's size.
#![allow(unused_unsafe)]
// The `avx512` feature states its own minimum Rust version (1.89).
#![allow(clippy::incompatible_msrv)]

pub(in crate::lanes) mod f64x8 {
    #[allow(clippy::wildcard_imports)]
    use core::arch::x86_64::*;

    pub(in crate::lanes) type V = __m512d;

    #[inline(always)]
    pub(in crate::lanes) const fn constant(lanes: [f64; 8]) -> V {
        // SAFETY: the register and the array have the same size, and every bit pattern is a
        // valid register.
        unsafe { core::mem::transmute::<[f64; 8], V>(lanes) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn splat(x: f64) -> V {
        unsafe { _mm512_set1_pd(x) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn from_array(lanes: [f64; 8]) -> V {
        unsafe { _mm512_loadu_pd(lanes.as_ptr()) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn to_array(v: V) -> [f64; 8] {
        let mut out = [0.0; 8];
        unsafe { _mm512_storeu_pd(out.as_mut_ptr(), v) };
        out
    }
    #[inline(always)]
    pub(in crate::lanes) fn add(a: V, b: V) -> V {
        unsafe { _mm512_add_pd(a, b) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn sub(a: V, b: V) -> V {
        unsafe { _mm512_sub_pd(a, b) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn mul(a: V, b: V) -> V {
        unsafe { _mm512_mul_pd(a, b) }
    }
    #[inline(always)]
    pub(in crate::lanes) fn div(a: V, b: V) -> V {
        unsafe { _mm512_div_pd(a, b) }
    }
    /// The sign bit flipped, as the scalar's `-x` (an integer XOR: AVX-512F has no `xor_pd`).
    #[inline(always)]
    pub(in crate::lanes) fn neg(a: V) -> V {
        unsafe {
            _mm512_castsi512_pd(_mm512_xor_si512(
                _mm512_castpd_si512(a),
                _mm512_set1_epi64(i64::MIN),
            ))
        }
    }
    /// Fused exactly where the scalar `Real::mul_add` is (std; AVX-512 implies FMA).
    #[inline(always)]
    pub(in crate::lanes) fn mul_add(a: V, b: V, c: V) -> V {
        #[cfg(feature = "std")]
        return unsafe { _mm512_fmadd_pd(a, b, c) };
        #[cfg(not(feature = "std"))]
        return unsafe { _mm512_add_pd(_mm512_mul_pd(a, b), c) };
    }
    /// 1 where `a > 0`, −1 where `a < 0`, else `a·0` (±0, or the NaN), as the scalar.
    #[inline(always)]
    pub(in crate::lanes) fn sign(a: V) -> V {
        unsafe {
            let zero = _mm512_setzero_pd();
            let gt = _mm512_cmp_pd_mask::<_CMP_GT_OQ>(a, zero);
            let lt = _mm512_cmp_pd_mask::<_CMP_LT_OQ>(a, zero);
            let rest = _mm512_mul_pd(a, zero);
            let ones = _mm512_mask_blend_pd(gt, rest, _mm512_set1_pd(1.0));
            _mm512_mask_blend_pd(lt, ones, _mm512_set1_pd(-1.0))
        }
    }
    #[inline(always)]
    pub(in crate::lanes) fn all_positive(a: V) -> bool {
        unsafe { _mm512_cmp_pd_mask::<_CMP_GT_OQ>(a, _mm512_setzero_pd()) == 0xff }
    }
    #[inline(always)]
    pub(in crate::lanes) fn all_eq(a: V, b: V) -> bool {
        unsafe { _mm512_cmp_pd_mask::<_CMP_EQ_OQ>(a, b) == 0xff }
    }
    /// The AVX2 kernels of `sin_cos_4` on each half; lanes outside their fast range by the
    /// scalar, as `F64x4`'s.
    #[inline(always)]
    pub(in crate::lanes) fn sin_cos(a: V) -> (V, V) {
        use crate::trig::avx2_f64;
        unsafe {
            let (lo, hi) = (_mm512_castpd512_pd256(a), _mm512_extractf64x4_pd::<1>(a));
            if avx2_f64::in_fast_range_v(lo) && avx2_f64::in_fast_range_v(hi) {
                let ((s0, c0), (s1, c1)) = (avx2_f64::fast_4_v(lo), avx2_f64::fast_4_v(hi));
                let join =
                    |l: __m256d, h: __m256d| _mm512_insertf64x4::<1>(_mm512_castpd256_pd512(l), h);
                return (join(s0, s1), join(c0, c1));
            }
        }
        let (s, c) = super::super::x86::one_by_one(to_array(a), crate::trig::sin_cos_f64);
        (from_array(s), from_array(c))
    }

    /// Eight registers of eight `f64` transposed: lane `l` of result `j` is lane `j` of
    /// `rows[l]` (unpacks of pairs, then exchanges of 128-bit blocks, twice).
    #[inline(always)]
    pub(in crate::lanes) fn transpose(rows: [V; 8]) -> [V; 8] {
        unsafe {
            // Lanes (2k, 2k+1) of each pair of rows interleaved.
            let t: [V; 8] = core::array::from_fn(|i| {
                let (a, b) = (rows[i & !1], rows[i | 1]);
                if i & 1 == 0 {
                    _mm512_unpacklo_pd(a, b)
                } else {
                    _mm512_unpackhi_pd(a, b)
                }
            });
            // Of each four rows, columns (0, 4), (1, 5), (2, 6), (3, 7): blocks 0 and 2 (or 1 and
            // 3) of two unpacked pairs.
            let u: [V; 8] = core::array::from_fn(|i| {
                let base = (i & 4) | (i & 1);
                let (a, b) = (t[base], t[base + 2]);
                if i & 2 == 0 {
                    _mm512_shuffle_f64x2::<0b10_00_10_00>(a, b)
                } else {
                    _mm512_shuffle_f64x2::<0b11_01_11_01>(a, b)
                }
            });
            // Column j: the blocks of rows 0 to 3 beside those of rows 4 to 7.
            core::array::from_fn(|j| {
                let base = j & 3;
                let (a, b) = (u[base], u[base + 4]);
                if j & 4 == 0 {
                    _mm512_shuffle_f64x2::<0b10_00_10_00>(a, b)
                } else {
                    _mm512_shuffle_f64x2::<0b11_01_11_01>(a, b)
                }
            })
        }
    }
}
