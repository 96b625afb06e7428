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

    /// A row of `N` columns of a tangent kept in the groups `at..at + Q` of the whole (the
    /// directions outside them zero).
    #[inline(always)]
    #[must_use]
    pub fn row_at<const N: usize>(self, at: usize) -> [T; N] {
        core::array::from_fn(|j| match (j / 8).checked_sub(at) {
            Some(g) if g < Q => self.0[g][j % 8],
            _ => T::ZERO,
        })
    }

    /// This tangent as groups `at..at + Q` of a wider one of `W` groups, zero elsewhere.
    #[inline(always)]
    #[must_use]
    pub fn widen<const W: usize>(self, at: usize) -> Tangent<T, W> {
        let mut wide = Tangent([[T::ZERO; 8]; W]);
        wide.0[at..at + Q].copy_from_slice(&self.0);
        wide
    }

    /// `c ∂v` added into groups `at..at + Q` of `acc` ([`Tangent::mul_add`] there, `acc` kept
    /// elsewhere).
    #[inline(always)]
    #[must_use]
    pub fn mul_add_into<const W: usize>(
        self,
        c: T,
        mut acc: Tangent<T, W>,
        at: usize,
    ) -> Tangent<T, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = T::oct_mul_add(x, c, acc.0[at + k]);
        }
        acc
    }

    /// `acc + ∂v`, `∂v` in groups `at..at + Q` of `acc`.
    #[inline(always)]
    #[must_use]
    pub fn add_into<const W: usize>(self, mut acc: Tangent<T, W>, at: usize) -> Tangent<T, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = T::oct_add(acc.0[at + k], x);
        }
        acc
    }

    /// `acc - ∂v`, `∂v` in groups `at..at + Q` of `acc`.
    #[inline(always)]
    #[must_use]
    pub fn sub_from<const W: usize>(self, mut acc: Tangent<T, W>, at: usize) -> Tangent<T, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = T::oct_sub(acc.0[at + k], x);
        }
        acc
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
        // Kept in group 1 of three: the other groups' lanes are zero, and every step is the
        // scalar one in group 1 alone.
        let wide: Tangent<T, 3> = Tangent([y, y, y]);
        let row: [T; 20] = a.row_at(1);
        assert!(row[..8].iter().chain(&row[16..]).all(|&v| v == T::ZERO));
        assert_eq!(row[8..16], x[..]);
        assert_eq!(a.widen::<3>(1).0, [[T::ZERO; 8], x, [T::ZERO; 8]]);
        for l in 0..8 {
            assert_eq!(a.mul_add_into(c, wide, 1).0[1][l], x[l].mul_add(c, y[l]));
            assert_eq!(a.add_into(wide, 1).0[1][l], y[l] + x[l]);
            assert_eq!(a.sub_from(wide, 1).0[1][l], y[l] - x[l]);
        }
        for step in [
            a.mul_add_into(c, wide, 1),
            a.add_into(wide, 1),
            a.sub_from(wide, 1),
        ] {
            assert_eq!((step.0[0], step.0[2]), (y, y));
        }
    }

    #[test]
    fn steps_are_the_scalar_operations_lane_by_lane() {
        agrees::<f64>();
        agrees::<f32>();
        agrees::<crate::lanes::F64x4>();
    }
}
