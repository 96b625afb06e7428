//! [`Real`] and [`RealScalar`] for `f64` and `f32`: the sines and cosines of `trig`, `mul_add`
//! fused where it is one instruction, and the derivatives' tangent steps on eight lanes (the
//! lane types of `lanes`). Apart from `real.rs`, which the lane types implement too, so that
//! the trait imports nothing of them.

use crate::real::{Real, RealScalar};

macro_rules! impl_real {
    ($t:ty, { $($oct:tt)* }, $sin_cos:path, $sin_cos_4:path, $sin_cos_8:path, $tanh:path) => {
        impl Real for $t {
            $($oct)*
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            #[inline(always)]
            #[allow(clippy::cast_possible_truncation)]
            fn from_f64(value: f64) -> Self {
                value as $t
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                $sin_cos(self)
            }
            #[inline(always)]
            fn sin(self) -> Self {
                $sin_cos(self).0
            }
            #[inline(always)]
            fn cos(self) -> Self {
                $sin_cos(self).1
            }
            #[inline(always)]
            fn mul_add(self, a: Self, b: Self) -> Self {
                // Only where it is one instruction: elsewhere std's `mul_add` is a slow
                // software routine.
                #[cfg(all(
                    feature = "std",
                    any(target_feature = "fma", target_arch = "aarch64")
                ))]
                return <$t>::mul_add(self, a, b);
                #[cfg(not(all(
                    feature = "std",
                    any(target_feature = "fma", target_arch = "aarch64")
                )))]
                return self * a + b;
            }
            #[inline(always)]
            fn sin_cos_4(x: [Self; 4]) -> ([Self; 4], [Self; 4]) {
                $sin_cos_4(x)
            }
            #[inline(always)]
            fn sin_cos_8(x: [Self; 8]) -> ([Self; 8], [Self; 8]) {
                $sin_cos_8(x)
            }
            #[inline(always)]
            fn sign(self) -> Self {
                // Two compares and selects, no branch; NaN fails both and passes through.
                if self > 0.0 {
                    1.0
                } else if self < 0.0 {
                    -1.0
                } else {
                    self * 0.0
                }
            }
            #[inline(always)]
            fn tanh(self) -> Self {
                $tanh(self)
            }
            #[inline(always)]
            fn all_positive(&self) -> bool {
                *self > 0.0
            }
        }

        impl RealScalar for $t {
            #[inline(always)]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
        }
    };
}

impl_real!(
    f64,
    {
        // The tangents' steps in eight lanes: one AVX-512 register, or two AVX.
        #[inline(always)]
        fn oct_mul_add(x: [f64; 8], c: f64, acc: [f64; 8]) -> [Self; 8] {
            crate::lanes::oct::mul_add(x, c, acc)
        }
        #[inline(always)]
        fn oct_scale(x: [f64; 8], c: f64) -> [Self; 8] {
            crate::lanes::oct::scale(x, c)
        }
        #[inline(always)]
        fn oct_add(a: [f64; 8], b: [f64; 8]) -> [Self; 8] {
            crate::lanes::oct::add(a, b)
        }
        #[inline(always)]
        fn oct_sub(a: [f64; 8], b: [f64; 8]) -> [Self; 8] {
            crate::lanes::oct::sub(a, b)
        }
        #[inline(always)]
        fn oct_neg(x: [f64; 8]) -> [Self; 8] {
            crate::lanes::oct::neg(x)
        }
        // And in four: one AVX register.
        #[inline(always)]
        fn quad_mul_add(x: [f64; 4], c: f64, acc: [f64; 4]) -> [Self; 4] {
            crate::lanes::F64x4::from_array(x)
                .mul_add(
                    crate::lanes::F64x4::splat(c),
                    crate::lanes::F64x4::from_array(acc),
                )
                .to_array()
        }
        #[inline(always)]
        fn quad_scale(x: [f64; 4], c: f64) -> [Self; 4] {
            (crate::lanes::F64x4::from_array(x) * crate::lanes::F64x4::splat(c)).to_array()
        }
        #[inline(always)]
        fn quad_add(a: [f64; 4], b: [f64; 4]) -> [Self; 4] {
            (crate::lanes::F64x4::from_array(a) + crate::lanes::F64x4::from_array(b)).to_array()
        }
        #[inline(always)]
        fn quad_sub(a: [f64; 4], b: [f64; 4]) -> [Self; 4] {
            (crate::lanes::F64x4::from_array(a) - crate::lanes::F64x4::from_array(b)).to_array()
        }
        #[inline(always)]
        fn quad_neg(x: [f64; 4]) -> [Self; 4] {
            (-crate::lanes::F64x4::from_array(x)).to_array()
        }
    },
    crate::trig::sin_cos_f64,
    crate::trig::sin_cos_4_f64,
    crate::trig::sin_cos_8_f64,
    libm::tanh
);
impl_real!(
    f32,
    {
        // The tangents' steps in eight lanes: one AVX register.
        #[inline(always)]
        fn oct_mul_add(x: [f32; 8], c: f32, acc: [f32; 8]) -> [Self; 8] {
            crate::lanes::F32x8::from_array(x)
                .mul_add(
                    crate::lanes::F32x8::splat(c),
                    crate::lanes::F32x8::from_array(acc),
                )
                .to_array()
        }
        #[inline(always)]
        fn oct_scale(x: [f32; 8], c: f32) -> [Self; 8] {
            (crate::lanes::F32x8::from_array(x) * crate::lanes::F32x8::splat(c)).to_array()
        }
        #[inline(always)]
        fn oct_add(a: [f32; 8], b: [f32; 8]) -> [Self; 8] {
            (crate::lanes::F32x8::from_array(a) + crate::lanes::F32x8::from_array(b)).to_array()
        }
        #[inline(always)]
        fn oct_sub(a: [f32; 8], b: [f32; 8]) -> [Self; 8] {
            (crate::lanes::F32x8::from_array(a) - crate::lanes::F32x8::from_array(b)).to_array()
        }
        #[inline(always)]
        fn oct_neg(x: [f32; 8]) -> [Self; 8] {
            (-crate::lanes::F32x8::from_array(x)).to_array()
        }
    },
    crate::trig::sin_cos_f32,
    crate::trig::sin_cos_4_f32,
    crate::trig::sin_cos_8_f32,
    tanh_f32
);

/// `f32` tanh through `f64`'s, rounded once: `libm::tanhf` is up to 2 ulp off.
#[inline(always)]
#[allow(clippy::cast_possible_truncation)]
fn tanh_f32(x: f32) -> f32 {
    libm::tanh(f64::from(x)) as f32
}
