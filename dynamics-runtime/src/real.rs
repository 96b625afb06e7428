//! Scalars that generated code computes with.

use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// What generated code computes with: a floating-point scalar (`f32`, for single-precision
/// FPUs, or `f64`: [`RealScalar`]), or several of them in vector lanes ([`crate::lanes`]:
/// `F64x4`, `F32x8`, …), one state per lane.
///
/// Sine and cosine come from this crate's own shared `sin_cos` (one range reduction for both,
/// within 1 ulp of std's in the common range; `libm` for arguments beyond 2^16 rad for `f64`
/// and 2^12 rad for `f32`), with or without the `std` feature.
///
/// Not ordered: a lane type has no order. Generated code's one comparison, the pivot test of
/// the methods that solve with the mass matrix, is [`Real::all_positive`]. `==` is true where
/// every lane is equal.
pub trait Real:
    Copy
    + PartialEq
    + core::fmt::Debug
    + Default
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// The nearest value to an `f64` constant (in every lane).
    fn from_f64(value: f64) -> Self;
    /// Sine and cosine, in this order.
    fn sin_cos(self) -> (Self, Self);
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// `self * a + b`, fused into one instruction with one rounding where the build has FMA
    /// (`-C target-cpu=native` on most x86-64 machines, every aarch64) and std; otherwise the
    /// two operations.
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// The sines and the cosines of four arguments, computed side by side (in vector
    /// registers on x86-64: SSE2 or AVX2 for `f64`, SSE for `f32`); each pair equals
    /// [`Real::sin_cos`] of its argument, bit for bit.
    fn sin_cos_4(x: [Self; 4]) -> ([Self; 4], [Self; 4]);
    /// The sines and the cosines of eight arguments, as two [`Real::sin_cos_4`] side by side
    /// behind one test of their range; each pair equals [`Real::sin_cos`] of its argument, bit
    /// for bit.
    fn sin_cos_8(x: [Self; 8]) -> ([Self; 8], [Self; 8]);
    /// The sign for Coulomb friction: −1, 0 or 1, with 0 at ±0 (a joint at rest gets no
    /// Coulomb torque), NaN for NaN. Not `f64::signum`, which is ±1 at ±0.
    fn sign(self) -> Self;
    /// Hyperbolic tangent, for the smooth Coulomb friction `f_c tanh(q̇ / ε)`: `libm`'s, with or
    /// without the `std` feature (`f32` through `f64`); within 2 ulp of std's in `f64`, 1 ulp
    /// of the exact value in `f32`.
    fn tanh(self) -> Self;
    /// Whether the value is positive (`> 0`, false for NaN), in every lane: the pivot test of
    /// the LDLᵀ factorization in the methods that solve with the mass matrix. On lanes, `false`
    /// where at least one lane is not positive, so that such a method's `Err` (or `None`) means
    /// that at least one lane's state failed, and says nothing of the others.
    ///
    /// By reference, as `>` takes its operands: generated code written `T::all_positive(&d)`
    /// compiles for `f32` and `f64` to the machine code of `d > T::ZERO`, instruction for
    /// instruction (by value, the compiler orders some operations differently).
    fn all_positive(&self) -> bool;

    /// Whether generated derivatives compute their tangents in lanes, across directions
    /// ([`crate::__private::Tangent`]), rather than column by column: for `f64` and `f32` where
    /// the build has AVX-512 and the `avx512` feature is on (eight `f64` directions in one of 32 registers; with AVX2 alone,
    /// two of 16, the Panda's ∂τ took 20 % fewer instructions, the 6-joint arms' up to 8 %
    /// more); not on the lane types, where each tangent would take eight of their registers.
    /// Where the two differ, `inverse_dynamics_derivatives` on lanes agrees with one state's to
    /// rounding, not bit for bit (the same sums in another order).
    #[doc(hidden)]
    const TANGENTS_IN_LANES: bool = cfg!(all(target_feature = "avx512f", feature = "avx512"));

    /// `c x + acc` on eight values, lane by lane as [`Real::mul_add`]: the step of the
    /// tangents that generated derivatives compute in lanes ([`crate::__private::Tangent`]),
    /// in vector registers for `f64` and `f32`, a loop otherwise.
    #[doc(hidden)]
    #[inline(always)]
    fn oct_mul_add(x: [Self; 8], c: Self, acc: [Self; 8]) -> [Self; 8] {
        core::array::from_fn(|l| x[l].mul_add(c, acc[l]))
    }
    /// `c x` on eight values.
    #[doc(hidden)]
    #[inline(always)]
    fn oct_scale(x: [Self; 8], c: Self) -> [Self; 8] {
        x.map(|x| x * c)
    }
    /// `a + b` on eight values.
    #[doc(hidden)]
    #[inline(always)]
    fn oct_add(a: [Self; 8], b: [Self; 8]) -> [Self; 8] {
        core::array::from_fn(|l| a[l] + b[l])
    }
    /// `a − b` on eight values.
    #[doc(hidden)]
    #[inline(always)]
    fn oct_sub(a: [Self; 8], b: [Self; 8]) -> [Self; 8] {
        core::array::from_fn(|l| a[l] - b[l])
    }
    /// `−x` on eight values.
    #[doc(hidden)]
    #[inline(always)]
    fn oct_neg(x: [Self; 8]) -> [Self; 8] {
        x.map(|x| -x)
    }

    /// `c x + acc` on four values, lane by lane as [`Real::mul_add`]: the step of tangents
    /// kept in groups of four ([`crate::__private::Tangent`] of `[T; 4]` groups), where a
    /// plan's lanes hold fewer directions than whole groups of eight would waste.
    #[doc(hidden)]
    #[inline(always)]
    fn quad_mul_add(x: [Self; 4], c: Self, acc: [Self; 4]) -> [Self; 4] {
        core::array::from_fn(|l| x[l].mul_add(c, acc[l]))
    }
    /// `c x` on four values.
    #[doc(hidden)]
    #[inline(always)]
    fn quad_scale(x: [Self; 4], c: Self) -> [Self; 4] {
        x.map(|x| x * c)
    }
    /// `a + b` on four values.
    #[doc(hidden)]
    #[inline(always)]
    fn quad_add(a: [Self; 4], b: [Self; 4]) -> [Self; 4] {
        core::array::from_fn(|l| a[l] + b[l])
    }
    /// `a − b` on four values.
    #[doc(hidden)]
    #[inline(always)]
    fn quad_sub(a: [Self; 4], b: [Self; 4]) -> [Self; 4] {
        core::array::from_fn(|l| a[l] - b[l])
    }
    /// `−x` on four values.
    #[doc(hidden)]
    #[inline(always)]
    fn quad_neg(x: [Self; 4]) -> [Self; 4] {
        x.map(|x| -x)
    }
}

/// One number, `f32` or `f64`: a [`Real`] that is ordered and converts to `f64`, and the
/// element of the lane types.
pub trait RealScalar: Real + PartialOrd {
    /// The value as `f64`.
    fn to_f64(self) -> f64;
}

#[cfg(test)]
mod tests {
    use super::{Real, RealScalar};

    #[test]
    fn sin_cos_agree_with_sin_and_cos() {
        for i in -40..=40 {
            let x = f64::from(i) * 0.37;
            let (s, c) = Real::sin_cos(x);
            assert_eq!(s, Real::sin(x));
            assert_eq!(c, Real::cos(x));
            assert!((s * s + c * c - 1.0).abs() < 1e-15);
            let (sf, cf) = Real::sin_cos(x as f32);
            assert!((f64::from(sf) - s).abs() < 1e-6);
            assert!((f64::from(cf) - c).abs() < 1e-6);
        }
    }

    #[test]
    fn conversions() {
        assert_eq!(<f32 as Real>::from_f64(0.5), 0.5f32);
        assert_eq!(RealScalar::to_f64(0.25f32), 0.25);
        assert!(Real::all_positive(&f64::MIN_POSITIVE));
        assert!(!Real::all_positive(&0.0f32) && !Real::all_positive(&f64::NAN));
        assert_eq!(<f64 as Real>::ZERO + <f64 as Real>::ONE, 1.0);
    }
}
