//! The x86-64 backends: one SSE2 register (`F64x2`, `F32x4`, in every x86-64 build) or one AVX
//! register (`F64x4`, `F32x8`, where the build enables AVX2; two SSE2 registers without), each
//! operation one instruction on all lanes, the same IEEE operation as the scalar's on each.
//!
//! SAFETY (every `unsafe` block of this file): the intrinsics require the target features of
//! their module (SSE2, or AVX and AVX2), which the build enables wherever the module is
//! compiled (the `cfg`s on the modules: SSE2 is part of every x86-64 target). Loads and stores
//! go through arrays of exactly the register's size. Newer compilers treat the intrinsics as
//! safe where the build enables their feature: hence `unused_unsafe` allowed.
#![allow(unused_unsafe)]

/// A backend module `$m`: the register `$v` of `$lanes` × `$e`, and its operations by the
/// intrinsics given.
macro_rules! x86_backend {
    (
        $m:ident, $e:ident, $lanes:literal, $v:ident,
        set1: $set1:ident, loadu: $loadu:ident, storeu: $storeu:ident,
        add: $add:ident, sub: $sub:ident, mul: $mul:ident, div: $div:ident,
        and: $and:ident, or: $or:ident, andnot: $andnot:ident, xor: $xor:ident,
        fmadd: $fmadd:ident, movemask: $movemask:ident,
        gt: $gt:expr, lt: $lt:expr, eq: $eq:expr,
        sin_cos: $sin_cos:path $(,)?
    ) => {
        pub(in crate::lanes) mod $m {
            #[allow(clippy::wildcard_imports)]
            use core::arch::x86_64::*;

            pub(in crate::lanes) type V = $v;

            /// All lanes set in a comparison's mask.
            const ALL: i32 = (1 << $lanes) - 1;

            #[inline(always)]
            pub(in crate::lanes) const fn constant(lanes: [$e; $lanes]) -> V {
                // SAFETY: the register and the array have the same size, and every bit pattern
                // is a valid register.
                unsafe { core::mem::transmute::<[$e; $lanes], V>(lanes) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn splat(x: $e) -> V {
                unsafe { $set1(x) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn from_array(lanes: [$e; $lanes]) -> V {
                unsafe { $loadu(lanes.as_ptr()) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn to_array(v: V) -> [$e; $lanes] {
                let mut out = [0.0; $lanes];
                unsafe { $storeu(out.as_mut_ptr(), v) };
                out
            }
            #[inline(always)]
            pub(in crate::lanes) fn add(a: V, b: V) -> V {
                unsafe { $add(a, b) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn sub(a: V, b: V) -> V {
                unsafe { $sub(a, b) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn mul(a: V, b: V) -> V {
                unsafe { $mul(a, b) }
            }
            #[inline(always)]
            pub(in crate::lanes) fn div(a: V, b: V) -> V {
                unsafe { $div(a, b) }
            }
            /// The sign bit flipped, as the scalar's `-x`.
            #[inline(always)]
            pub(in crate::lanes) fn neg(a: V) -> V {
                unsafe { $xor(a, $set1(-0.0)) }
            }
            /// Fused exactly where the scalar `Real::mul_add` is (std and FMA; x86-64 is not
            /// aarch64), else a product and a sum, two roundings as there.
            #[inline(always)]
            pub(in crate::lanes) fn mul_add(a: V, b: V, c: V) -> V {
                #[cfg(all(feature = "std", target_feature = "fma"))]
                return unsafe { $fmadd(a, b, c) };
                #[cfg(not(all(feature = "std", target_feature = "fma")))]
                return unsafe { $add($mul(a, b), c) };
            }
            /// 1 where `a > 0`, −1 where `a < 0`, else `a·0` (±0, or the NaN), as the scalar.
            #[inline(always)]
            pub(in crate::lanes) fn sign(a: V) -> V {
                unsafe {
                    let zero = $set1(0.0);
                    let (gt, lt) = (($gt)(a, zero), ($lt)(a, zero));
                    let ones = $or($and(gt, $set1(1.0)), $and(lt, $set1(-1.0)));
                    $or(ones, $andnot($or(gt, lt), $mul(a, zero)))
                }
            }
            #[inline(always)]
            pub(in crate::lanes) fn all_positive(a: V) -> bool {
                unsafe { $movemask(($gt)(a, $set1(0.0))) == ALL }
            }
            #[inline(always)]
            pub(in crate::lanes) fn all_eq(a: V, b: V) -> bool {
                unsafe { $movemask(($eq)(a, b)) == ALL }
            }
            #[inline(always)]
            pub(in crate::lanes) fn sin_cos(a: V) -> (V, V) {
                $sin_cos(a)
            }
        }
    };
}

x86_backend!(
    f64x2, f64, 2, __m128d,
    set1: _mm_set1_pd, loadu: _mm_loadu_pd, storeu: _mm_storeu_pd,
    add: _mm_add_pd, sub: _mm_sub_pd, mul: _mm_mul_pd, div: _mm_div_pd,
    and: _mm_and_pd, or: _mm_or_pd, andnot: _mm_andnot_pd, xor: _mm_xor_pd,
    fmadd: _mm_fmadd_pd, movemask: _mm_movemask_pd,
    gt: |a, b| _mm_cmpgt_pd(a, b), lt: |a, b| _mm_cmplt_pd(a, b), eq: |a, b| _mm_cmpeq_pd(a, b),
    sin_cos: super::sin_cos_f64x2,
);

x86_backend!(
    f32x4, f32, 4, __m128,
    set1: _mm_set1_ps, loadu: _mm_loadu_ps, storeu: _mm_storeu_ps,
    add: _mm_add_ps, sub: _mm_sub_ps, mul: _mm_mul_ps, div: _mm_div_ps,
    and: _mm_and_ps, or: _mm_or_ps, andnot: _mm_andnot_ps, xor: _mm_xor_ps,
    fmadd: _mm_fmadd_ps, movemask: _mm_movemask_ps,
    gt: |a, b| _mm_cmpgt_ps(a, b), lt: |a, b| _mm_cmplt_ps(a, b), eq: |a, b| _mm_cmpeq_ps(a, b),
    sin_cos: super::sin_cos_f32x4,
);

#[cfg(target_feature = "avx2")]
x86_backend!(
    f64x4, f64, 4, __m256d,
    set1: _mm256_set1_pd, loadu: _mm256_loadu_pd, storeu: _mm256_storeu_pd,
    add: _mm256_add_pd, sub: _mm256_sub_pd, mul: _mm256_mul_pd, div: _mm256_div_pd,
    and: _mm256_and_pd, or: _mm256_or_pd, andnot: _mm256_andnot_pd, xor: _mm256_xor_pd,
    fmadd: _mm256_fmadd_pd, movemask: _mm256_movemask_pd,
    gt: |a, b| _mm256_cmp_pd::<_CMP_GT_OQ>(a, b),
    lt: |a, b| _mm256_cmp_pd::<_CMP_LT_OQ>(a, b),
    eq: |a, b| _mm256_cmp_pd::<_CMP_EQ_OQ>(a, b),
    sin_cos: super::sin_cos_f64x4,
);

/// Four registers of four `f64` transposed: lane `l` of result `j` is lane `j` of `rows[l]`
/// (unpacks within the 128-bit halves, then the halves exchanged).
#[cfg(target_feature = "avx2")]
#[inline(always)]
pub(in crate::lanes) fn transpose_f64x4(rows: [__m256d; 4]) -> [__m256d; 4] {
    use core::arch::x86_64::{_mm256_permute2f128_pd, _mm256_unpackhi_pd, _mm256_unpacklo_pd};
    unsafe {
        // [r0₀ r1₀ r0₂ r1₂], [r0₁ r1₁ r0₃ r1₃], and the same of rows 2 and 3.
        let (a, b) = (
            _mm256_unpacklo_pd(rows[0], rows[1]),
            _mm256_unpackhi_pd(rows[0], rows[1]),
        );
        let (c, d) = (
            _mm256_unpacklo_pd(rows[2], rows[3]),
            _mm256_unpackhi_pd(rows[2], rows[3]),
        );
        [
            _mm256_permute2f128_pd::<0x20>(a, c),
            _mm256_permute2f128_pd::<0x20>(b, d),
            _mm256_permute2f128_pd::<0x31>(a, c),
            _mm256_permute2f128_pd::<0x31>(b, d),
        ]
    }
}

/// Eight registers of eight `f32` transposed: lane `l` of result `j` is lane `j` of `rows[l]`
/// (unpacks of pairs of rows, shuffles of pairs of those within the 128-bit halves, then the
/// halves exchanged).
#[cfg(target_feature = "avx2")]
#[inline(always)]
pub(in crate::lanes) fn transpose_f32x8(rows: [__m256; 8]) -> [__m256; 8] {
    use core::arch::x86_64::{
        _mm256_permute2f128_ps, _mm256_shuffle_ps, _mm256_unpackhi_ps, _mm256_unpacklo_ps,
    };
    unsafe {
        // t[2p]: lanes 0, 1 (and 4, 5) of rows 2p and 2p + 1 interleaved; t[2p + 1]: 2, 3 (6, 7).
        let t: [__m256; 8] = core::array::from_fn(|i| {
            let (a, b) = (rows[i & !1], rows[i | 1]);
            if i & 1 == 0 {
                _mm256_unpacklo_ps(a, b)
            } else {
                _mm256_unpackhi_ps(a, b)
            }
        });
        // Of each four rows, columns (0, 4), (1, 5), (2, 6), (3, 7), in u[4h..4h + 4].
        let u: [__m256; 8] = core::array::from_fn(|i| {
            let base = (i & 4) | ((i >> 1) & 1);
            let (a, b) = (t[base], t[base + 2]);
            if i & 1 == 0 {
                _mm256_shuffle_ps::<0x44>(a, b)
            } else {
                _mm256_shuffle_ps::<0xee>(a, b)
            }
        });
        // Column j: the halves of rows 0 to 3 and 4 to 7.
        core::array::from_fn(|j| {
            let (a, b) = (u[j & 3], u[(j & 3) + 4]);
            if j & 4 == 0 {
                _mm256_permute2f128_ps::<0x20>(a, b)
            } else {
                _mm256_permute2f128_ps::<0x31>(a, b)
            }
        })
    }
}

#[cfg(target_feature = "avx2")]
x86_backend!(
    f32x8, f32, 8, __m256,
    set1: _mm256_set1_ps, loadu: _mm256_loadu_ps, storeu: _mm256_storeu_ps,
    add: _mm256_add_ps, sub: _mm256_sub_ps, mul: _mm256_mul_ps, div: _mm256_div_ps,
    and: _mm256_and_ps, or: _mm256_or_ps, andnot: _mm256_andnot_ps, xor: _mm256_xor_ps,
    fmadd: _mm256_fmadd_ps, movemask: _mm256_movemask_ps,
    gt: |a, b| _mm256_cmp_ps::<_CMP_GT_OQ>(a, b),
    lt: |a, b| _mm256_cmp_ps::<_CMP_LT_OQ>(a, b),
    eq: |a, b| _mm256_cmp_ps::<_CMP_EQ_OQ>(a, b),
    sin_cos: super::sin_cos_f32x8,
);

/// A backend module `$m` of `2 × $half_lanes` lanes of `$e` as two registers of the backend
/// `$half`, for builds without AVX2: each operation on both halves, which run side by side.
/// `#[inline]`, not `always`: optimized builds inline them all the same, and unoptimized ones
/// keep each operation's temporaries in its own frame rather than in the generated function's
/// (whose frame would otherwise outgrow a test thread's stack on the larger robots).
#[cfg(not(all(
    target_feature = "avx2",
    target_feature = "avx512f",
    feature = "avx512"
)))]
macro_rules! pair_backend {
    ($m:ident, $e:ident, $lanes:literal, $half:ident, $half_lanes:literal) => {
        pub(in crate::lanes) mod $m {
            use super::$half as h;

            /// Lanes `0..$half_lanes` in the first register.
            pub(in crate::lanes) type V = [h::V; 2];

            #[inline]
            pub(in crate::lanes) const fn constant(lanes: [$e; $lanes]) -> V {
                // SAFETY: the two registers and the array have the same size and layout (the
                // first register holds the first half), and every bit pattern is valid.
                unsafe { core::mem::transmute::<[$e; $lanes], V>(lanes) }
            }
            #[inline]
            pub(in crate::lanes) fn splat(x: $e) -> V {
                [h::splat(x); 2]
            }
            #[inline]
            pub(in crate::lanes) fn from_array(lanes: [$e; $lanes]) -> V {
                let half = |k: usize| core::array::from_fn(|l| lanes[k * $half_lanes + l]);
                [h::from_array(half(0)), h::from_array(half(1))]
            }
            #[inline]
            pub(in crate::lanes) fn to_array(v: V) -> [$e; $lanes] {
                let halves = [h::to_array(v[0]), h::to_array(v[1])];
                core::array::from_fn(|l| halves[l / $half_lanes][l % $half_lanes])
            }
            pair_backend!(@binary add sub mul div all_eq);
            #[inline]
            pub(in crate::lanes) fn neg(a: V) -> V {
                [h::neg(a[0]), h::neg(a[1])]
            }
            #[inline]
            pub(in crate::lanes) fn mul_add(a: V, b: V, c: V) -> V {
                [h::mul_add(a[0], b[0], c[0]), h::mul_add(a[1], b[1], c[1])]
            }
            #[inline]
            pub(in crate::lanes) fn sign(a: V) -> V {
                [h::sign(a[0]), h::sign(a[1])]
            }
            /// Both halves tested, with no early exit.
            #[inline]
            pub(in crate::lanes) fn all_positive(a: V) -> bool {
                h::all_positive(a[0]) & h::all_positive(a[1])
            }
            #[inline]
            pub(in crate::lanes) fn sin_cos(a: V) -> (V, V) {
                let ((s0, c0), (s1, c1)) = (h::sin_cos(a[0]), h::sin_cos(a[1]));
                ([s0, s1], [c0, c1])
            }
        }
    };
    (@binary $($f:ident)*) => {$(
        #[inline]
        pub(in crate::lanes) fn $f(a: V, b: V) -> pair_backend!(@output $f) {
            pair_backend!(@combine $f, h::$f(a[0], b[0]), h::$f(a[1], b[1]))
        }
    )*};
    (@output all_eq) => { bool };
    (@output $f:ident) => { V };
    (@combine all_eq, $x:expr, $y:expr) => { $x & $y };
    (@combine $f:ident, $x:expr, $y:expr) => { [$x, $y] };
}

#[cfg(not(target_feature = "avx2"))]
pair_backend!(f64x4, f64, 4, f64x2, 2);
// Two AVX registers (or four SSE2 registers) without AVX-512 and the `avx512` feature.
#[cfg(not(all(target_feature = "avx512f", feature = "avx512")))]
pair_backend!(f64x8, f64, 8, f64x4, 4);
#[cfg(not(target_feature = "avx2"))]
pair_backend!(f32x8, f32, 8, f32x4, 4);

use crate::trig::{sin_cos_f32, sin_cos_f64, sse2_f64, sse_f32};
use core::arch::x86_64::{__m128, __m128d};
#[cfg(target_feature = "avx2")]
use {
    crate::trig::avx2_f64,
    core::arch::x86_64::{
        __m256, __m256d, _mm256_castps256_ps128, _mm256_extractf128_ps, _mm256_set_m128,
    },
};

/// Lanes outside the kernels' fast range (tiny, huge, infinite or NaN): each by the scalar
/// `sin_cos`, which takes the same path for an argument in the range and its own for the
/// others, so every lane is the scalar's.
#[cold]
#[inline(never)]
pub(in crate::lanes) fn one_by_one<E: Copy, const L: usize>(
    x: [E; L],
    sin_cos: impl Fn(E) -> (E, E),
) -> ([E; L], [E; L]) {
    let both = x.map(sin_cos);
    (both.map(|p| p.0), both.map(|p| p.1))
}

/// Sines and cosines of two `f64` lanes: the SSE2 kernels of `sin_cos_4` on one register.
#[inline(always)]
fn sin_cos_f64x2(x: __m128d) -> (__m128d, __m128d) {
    unsafe {
        if sse2_f64::in_fast_range_v(x) {
            return sse2_f64::fast_2_v(x);
        }
    }
    let (s, c) = one_by_one(f64x2::to_array(x), sin_cos_f64);
    (f64x2::from_array(s), f64x2::from_array(c))
}

/// Sines and cosines of four `f32` lanes: the SSE kernels of `sin_cos_4`.
#[inline(always)]
fn sin_cos_f32x4(x: __m128) -> (__m128, __m128) {
    unsafe {
        if sse_f32::in_fast_range_v(x) {
            return sse_f32::fast_4_v(x);
        }
    }
    let (s, c) = one_by_one(f32x4::to_array(x), sin_cos_f32);
    (f32x4::from_array(s), f32x4::from_array(c))
}

/// Sines and cosines of four `f64` lanes: the AVX2 kernels of `sin_cos_4`.
#[cfg(target_feature = "avx2")]
#[inline(always)]
fn sin_cos_f64x4(x: __m256d) -> (__m256d, __m256d) {
    unsafe {
        if avx2_f64::in_fast_range_v(x) {
            return avx2_f64::fast_4_v(x);
        }
    }
    let (s, c) = one_by_one(f64x4::to_array(x), sin_cos_f64);
    (f64x4::from_array(s), f64x4::from_array(c))
}

/// Sines and cosines of eight `f32` lanes: the SSE kernels on each half.
#[cfg(target_feature = "avx2")]
#[inline(always)]
fn sin_cos_f32x8(x: __m256) -> (__m256, __m256) {
    unsafe {
        let (lo, hi) = (_mm256_castps256_ps128(x), _mm256_extractf128_ps::<1>(x));
        if sse_f32::in_fast_range_v(lo) && sse_f32::in_fast_range_v(hi) {
            let ((s0, c0), (s1, c1)) = (sse_f32::fast_4_v(lo), sse_f32::fast_4_v(hi));
            return (_mm256_set_m128(s1, s0), _mm256_set_m128(c1, c0));
        }
    }
    let (s, c) = one_by_one(f32x8::to_array(x), sin_cos_f32);
    (f32x8::from_array(s), f32x8::from_array(c))
}
