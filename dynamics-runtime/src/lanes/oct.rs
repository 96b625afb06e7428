//! Eight `f64` lanes for the tangents of generated derivatives ([`crate::__private::Tangent`]):
//! one AVX-512 register where the build enables AVX-512F and the `avx512` feature is on (32 of them, so that a Jacobian's
//! rows stay in registers), else two [`F64x4`]. The same IEEE operations as the scalar's on
//! each lane, fused exactly where `Real::mul_add` is (std and FMA).
//!
//! SAFETY (every `unsafe` block of this file): the intrinsics require AVX-512F, which the
//! `cfg` on their module makes the build enable; loads and stores go through arrays of
//! exactly the register's size.
#![allow(unused_unsafe)]
// Behind the `avx512` feature, which states its own minimum Rust version (1.89).
#![allow(clippy::incompatible_msrv)]

#[cfg(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512"))]
mod backend {
    #[allow(clippy::wildcard_imports)]
    use core::arch::x86_64::*;

    type V = __m512d;

    #[inline(always)]
    fn load(x: [f64; 8]) -> V {
        unsafe { _mm512_loadu_pd(x.as_ptr()) }
    }
    #[inline(always)]
    fn store(v: V) -> [f64; 8] {
        let mut out = [0.0; 8];
        unsafe { _mm512_storeu_pd(out.as_mut_ptr(), v) };
        out
    }
    #[inline(always)]
    pub(crate) fn mul_add(x: [f64; 8], c: f64, acc: [f64; 8]) -> [f64; 8] {
        let (x, c, acc) = (load(x), unsafe { _mm512_set1_pd(c) }, load(acc));
        #[cfg(all(feature = "std", target_feature = "fma"))]
        return store(unsafe { _mm512_fmadd_pd(x, c, acc) });
        #[cfg(not(all(feature = "std", target_feature = "fma")))]
        return store(unsafe { _mm512_add_pd(_mm512_mul_pd(x, c), acc) });
    }
    #[inline(always)]
    pub(crate) fn scale(x: [f64; 8], c: f64) -> [f64; 8] {
        store(unsafe { _mm512_mul_pd(load(x), _mm512_set1_pd(c)) })
    }
    #[inline(always)]
    pub(crate) fn add(a: [f64; 8], b: [f64; 8]) -> [f64; 8] {
        store(unsafe { _mm512_add_pd(load(a), load(b)) })
    }
    #[inline(always)]
    pub(crate) fn sub(a: [f64; 8], b: [f64; 8]) -> [f64; 8] {
        store(unsafe { _mm512_sub_pd(load(a), load(b)) })
    }
    /// The sign bit flipped, as the scalar's `-x` (an integer xor: AVX-512F has no `f64` one).
    #[inline(always)]
    pub(crate) fn neg(x: [f64; 8]) -> [f64; 8] {
        let sign = unsafe { _mm512_set1_epi64(i64::MIN) };
        store(unsafe { _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(load(x)), sign)) })
    }
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512")))]
mod backend {
    use crate::lanes::F64x4;
    use crate::real::Real;

    /// The two halves of eight lanes, each operated on by `f`.
    #[inline(always)]
    fn halves(a: [f64; 8], b: [f64; 8], f: impl Fn(F64x4, F64x4) -> F64x4) -> [f64; 8] {
        let split = |x: [f64; 8]| {
            let lo: [f64; 4] = core::array::from_fn(|l| x[l]);
            let hi: [f64; 4] = core::array::from_fn(|l| x[l + 4]);
            (F64x4::from_array(lo), F64x4::from_array(hi))
        };
        let ((a0, a1), (b0, b1)) = (split(a), split(b));
        let (lo, hi) = (f(a0, b0).to_array(), f(a1, b1).to_array());
        core::array::from_fn(|l| if l < 4 { lo[l] } else { hi[l - 4] })
    }
    #[inline(always)]
    pub(crate) fn mul_add(x: [f64; 8], c: f64, acc: [f64; 8]) -> [f64; 8] {
        let c = F64x4::splat(c);
        halves(x, acc, |x, acc| x.mul_add(c, acc))
    }
    #[inline(always)]
    pub(crate) fn scale(x: [f64; 8], c: f64) -> [f64; 8] {
        let c = F64x4::splat(c);
        halves(x, x, |x, _| x * c)
    }
    #[inline(always)]
    pub(crate) fn add(a: [f64; 8], b: [f64; 8]) -> [f64; 8] {
        halves(a, b, |a, b| a + b)
    }
    #[inline(always)]
    pub(crate) fn sub(a: [f64; 8], b: [f64; 8]) -> [f64; 8] {
        halves(a, b, |a, b| a - b)
    }
    #[inline(always)]
    pub(crate) fn neg(x: [f64; 8]) -> [f64; 8] {
        halves(x, x, |x, _| -x)
    }
}

pub(crate) use backend::{add, mul_add, neg, scale, sub};
