//! The portable backend: the lanes as a plain array, each operation the scalar's on every
//! lane (so bit for bit the scalar's by construction). Compilers vectorize the loops where the
//! target has vector registers.

/// A backend module `$m` of `$lanes` × `$e`, its sines and cosines by `$sin_cos`.
macro_rules! portable_backend {
    ($m:ident, $e:ident, $lanes:literal, $sin_cos:expr) => {
        pub(in crate::lanes) mod $m {
            use crate::real::Real;

            pub(in crate::lanes) type V = [$e; $lanes];

            #[inline(always)]
            pub(in crate::lanes) const fn constant(lanes: [$e; $lanes]) -> V {
                lanes
            }
            #[inline(always)]
            pub(in crate::lanes) fn splat(x: $e) -> V {
                [x; $lanes]
            }
            #[inline(always)]
            pub(in crate::lanes) fn from_array(lanes: [$e; $lanes]) -> V {
                lanes
            }
            #[inline(always)]
            pub(in crate::lanes) fn to_array(v: V) -> [$e; $lanes] {
                v
            }
            #[inline(always)]
            fn zip(a: V, b: V, f: impl Fn($e, $e) -> $e) -> V {
                core::array::from_fn(|l| f(a[l], b[l]))
            }
            #[inline(always)]
            pub(in crate::lanes) fn add(a: V, b: V) -> V {
                zip(a, b, |x, y| x + y)
            }
            #[inline(always)]
            pub(in crate::lanes) fn sub(a: V, b: V) -> V {
                zip(a, b, |x, y| x - y)
            }
            #[inline(always)]
            pub(in crate::lanes) fn mul(a: V, b: V) -> V {
                zip(a, b, |x, y| x * y)
            }
            #[inline(always)]
            pub(in crate::lanes) fn div(a: V, b: V) -> V {
                zip(a, b, |x, y| x / y)
            }
            #[inline(always)]
            pub(in crate::lanes) fn neg(a: V) -> V {
                a.map(|x| -x)
            }
            #[inline(always)]
            pub(in crate::lanes) fn mul_add(a: V, b: V, c: V) -> V {
                core::array::from_fn(|l| Real::mul_add(a[l], b[l], c[l]))
            }
            #[inline(always)]
            pub(in crate::lanes) fn sign(a: V) -> V {
                a.map(Real::sign)
            }
            /// Every lane tested, with no early exit (one branch at the end).
            #[inline(always)]
            pub(in crate::lanes) fn all_positive(a: V) -> bool {
                a.iter().fold(true, |all, &x| all & (x > 0.0))
            }
            #[inline(always)]
            pub(in crate::lanes) fn all_eq(a: V, b: V) -> bool {
                a == b
            }
            #[inline(always)]
            pub(in crate::lanes) fn sin_cos(a: V) -> (V, V) {
                $sin_cos(a)
            }
        }
    };
}

// Each also in test builds, where `tests.rs` checks it on every target.
#[cfg(any(test, not(target_arch = "x86_64")))]
portable_backend!(f64x4, f64, 4, <f64 as Real>::sin_cos_4);
#[cfg(any(test, not(target_arch = "x86_64")))]
portable_backend!(f64x8, f64, 8, <f64 as Real>::sin_cos_8);
#[cfg(any(test, not(target_arch = "x86_64")))]
portable_backend!(f32x8, f32, 8, <f32 as Real>::sin_cos_8);
#[cfg(any(test, not(target_arch = "x86_64")))]
portable_backend!(f32x4, f32, 4, <f32 as Real>::sin_cos_4);
#[cfg(any(test, not(target_arch = "x86_64")))]
portable_backend!(f64x2, f64, 2, |a: [f64; 2]| {
    let (s0, c0) = Real::sin_cos(a[0]);
    let (s1, c1) = Real::sin_cos(a[1]);
    ([s0, s1], [c0, c1])
});
