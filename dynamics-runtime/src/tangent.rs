//! Tangents in lanes: the directional derivatives of one value side by side, for the
//! derivatives that generated code computes across directions rather than states.
//!
//! Forward differentiation of a straight-line program computes, for every value `v`, its
//! tangent `∂v/∂x = (∂v/∂x_1, …, ∂v/∂x_n)`: `∂(a + b) = ∂a + ∂b`, `∂(a b) = b ∂a + a ∂b`. The
//! n components undergo the same operations on different numbers, so they go in lanes, one
//! direction per lane, in groups of eight ([`Real::oct_mul_add`]: one AVX-512 register of `f64`
//! or two AVX, one AVX register of `f32`), a value's scalar broadcast to every lane. Lane `l` computes
//! what one scalar derivative by `x_l` would, operation for operation.

use crate::real::Real;
use core::ops::{Add, Neg, Sub};

/// The directional derivatives of one value in `Q` groups of eight lanes, lane `l` its
/// derivative by `x_l` (the lanes past the last direction zero).
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangent<T, const Q: usize>(pub [[T; 8]; Q]);

impl<T: Real, const Q: usize> Tangent<T, Q> {
    /// `c ∂v`: every lane times the scalar `c`.
    #[inline(always)]
    #[must_use]
    pub fn scale(self, c: T) -> Self {
        Tangent(self.0.map(|x| T::oct_scale(x, c)))
    }

    /// `c ∂v + acc`, lane by lane as [`Real::mul_add`] (fused where the build has FMA).
    #[inline(always)]
    #[must_use]
    pub fn mul_add(self, c: T, acc: Self) -> Self {
        Tangent(core::array::from_fn(|k| {
            T::oct_mul_add(self.0[k], c, acc.0[k])
        }))
    }

    /// The first `N` lanes: a row of a Jacobian of `N` columns.
    #[inline(always)]
    #[must_use]
    pub fn row<const N: usize>(self) -> [T; N] {
        core::array::from_fn(|j| self.0[j / 8][j % 8])
    }
}

impl<T: Real, const Q: usize> Add for Tangent<T, Q> {
    type Output = Self;
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        Tangent(core::array::from_fn(|k| T::oct_add(self.0[k], other.0[k])))
    }
}

impl<T: Real, const Q: usize> Sub for Tangent<T, Q> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        Tangent(core::array::from_fn(|k| T::oct_sub(self.0[k], other.0[k])))
    }
}

impl<T: Real, const Q: usize> Neg for Tangent<T, Q> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Tangent(self.0.map(T::oct_neg))
    }
}

#[cfg(test)]
mod tests {
    use super::Tangent;
    use crate::real::Real;

    /// Eight lanes of arbitrary values, shifted by `k`.
    fn lanes<T: Real>(k: f64) -> [T; 8] {
        core::array::from_fn(|l| T::from_f64((l as f64 + k) * 0.37 - 1.1))
    }

    /// Each lane of every step is the scalar operation on that lane, bit for bit.
    fn agrees<T: Real>() {
        let (x, y, c) = (lanes::<T>(0.0), lanes::<T>(3.5), T::from_f64(-0.713));
        let (a, b) = (Tangent([x]), Tangent([y]));
        for l in 0..8 {
            assert_eq!(a.mul_add(c, b).0[0][l], x[l].mul_add(c, y[l]));
            assert_eq!(a.scale(c).0[0][l], x[l] * c);
            assert_eq!((a + b).0[0][l], x[l] + y[l]);
            assert_eq!((a - b).0[0][l], x[l] - y[l]);
            assert_eq!((-a).0[0][l], -x[l]);
        }
        let row: [T; 7] = a.row();
        assert_eq!(row[..], x[..7]);
    }

    #[test]
    fn steps_are_the_scalar_operations_lane_by_lane() {
        agrees::<f64>();
        agrees::<f32>();
        agrees::<crate::lanes::F64x4>();
    }
}
