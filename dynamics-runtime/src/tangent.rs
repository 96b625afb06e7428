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

/// Keeps the stack frame of the function this is inlined into aligned to 64 bytes where `T`'s
/// code fills vector registers (tangents in AVX-512 lanes, or a batch's lanes of 32 bytes or
/// more). The derivatives are straight-line code that spills hundreds of those registers: LLVM
/// aligns its spill slots only in a frame it realigns anyway, which it decides before register
/// allocation, from the stack objects alone. A 64-byte slot whose address escapes is such an
/// object; without it the slots are 16-byte aligned, and three spills of a 64-byte register in
/// four straddle two cache lines (the Panda's `forward_dynamics_derivatives` 13-16 % slower on
/// an Intel Xeon). Nothing for a scalar `T` without lanes.
#[doc(hidden)]
#[inline(always)]
pub fn align_stack<T: Real>() {
    if T::TANGENTS_IN_LANES || core::mem::size_of::<T>() >= 32 {
        #[repr(C, align(64))]
        struct Line([u8; 64]);
        let mut line = core::mem::MaybeUninit::<Line>::uninit();
        core::hint::black_box(line.as_mut_ptr());
    }
}

/// A group of lanes a tangent is kept in: eight (`[T; 8]`, one AVX-512 register of `f64`) or
/// four (`[T; 4]`, one AVX register), each lane's step [`Real::oct_mul_add`] or
/// [`Real::quad_mul_add`] and the like.
#[doc(hidden)]
pub trait Group: Copy {
    /// The scalar of each lane.
    type T: Real;
    /// The lanes in a group.
    const WIDTH: usize;
    /// Every lane zero.
    const ZERO: Self;
    /// `c x + acc`, lane by lane.
    fn mul_add(self, c: Self::T, acc: Self) -> Self;
    /// `c x`.
    fn scale(self, c: Self::T) -> Self;
    /// `a + b`.
    fn add(self, b: Self) -> Self;
    /// `a − b`.
    fn sub(self, b: Self) -> Self;
    /// `−x`.
    fn neg(self) -> Self;
    /// Lane `l`.
    fn lane(&self, l: usize) -> Self::T;
}

/// The groups of eight and four lanes, through `$mul_add` and the like.
macro_rules! group {
    ($w:literal, $mul_add:ident, $scale:ident, $add:ident, $sub:ident, $neg:ident) => {
        impl<T: Real> Group for [T; $w] {
            type T = T;
            const WIDTH: usize = $w;
            const ZERO: Self = [T::ZERO; $w];
            #[inline(always)]
            fn mul_add(self, c: T, acc: Self) -> Self {
                T::$mul_add(self, c, acc)
            }
            #[inline(always)]
            fn scale(self, c: T) -> Self {
                T::$scale(self, c)
            }
            #[inline(always)]
            fn add(self, b: Self) -> Self {
                T::$add(self, b)
            }
            #[inline(always)]
            fn sub(self, b: Self) -> Self {
                T::$sub(self, b)
            }
            #[inline(always)]
            fn neg(self) -> Self {
                T::$neg(self)
            }
            #[inline(always)]
            fn lane(&self, l: usize) -> T {
                self[l]
            }
        }
    };
}
group!(8, oct_mul_add, oct_scale, oct_add, oct_sub, oct_neg);
group!(4, quad_mul_add, quad_scale, quad_add, quad_sub, quad_neg);

/// The directional derivatives of one value in `Q` groups of lanes (`G`: `[T; 8]` or
/// `[T; 4]`), lane `l` its derivative by `x_l` (the lanes past the last direction zero).
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangent<G, const Q: usize>(pub [G; Q]);

impl<G: Group, const Q: usize> Tangent<G, Q> {
    /// `c ∂v`: every lane times the scalar `c`.
    #[inline(always)]
    #[must_use]
    pub fn scale(self, c: G::T) -> Self {
        Tangent(self.0.map(|x| x.scale(c)))
    }

    /// `c ∂v + acc`, lane by lane as [`Real::mul_add`] (fused where the build has FMA).
    #[inline(always)]
    #[must_use]
    pub fn mul_add(self, c: G::T, acc: Self) -> Self {
        Tangent(core::array::from_fn(|k| self.0[k].mul_add(c, acc.0[k])))
    }

    /// The first `N` lanes: a row of a Jacobian of `N` columns.
    #[inline(always)]
    #[must_use]
    pub fn row<const N: usize>(self) -> [G::T; N] {
        core::array::from_fn(|j| self.0[j / G::WIDTH].lane(j % G::WIDTH))
    }

    /// A row of `N` columns of a tangent kept in the groups `at..at + Q` of the whole (the
    /// directions outside them zero).
    #[inline(always)]
    #[must_use]
    pub fn row_at<const N: usize>(self, at: usize) -> [G::T; N] {
        core::array::from_fn(|j| match (j / G::WIDTH).checked_sub(at) {
            Some(g) if g < Q => self.0[g].lane(j % G::WIDTH),
            _ => G::T::ZERO,
        })
    }

    /// This tangent as groups `at..at + Q` of a wider one of `W` groups, zero elsewhere.
    #[inline(always)]
    #[must_use]
    pub fn widen<const W: usize>(self, at: usize) -> Tangent<G, W> {
        let mut wide = Tangent([G::ZERO; W]);
        wide.0[at..at + Q].copy_from_slice(&self.0);
        wide
    }

    /// `c ∂v` added into groups `at..at + Q` of `acc` ([`Tangent::mul_add`] there, `acc` kept
    /// elsewhere).
    #[inline(always)]
    #[must_use]
    pub fn mul_add_into<const W: usize>(
        self,
        c: G::T,
        mut acc: Tangent<G, W>,
        at: usize,
    ) -> Tangent<G, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = x.mul_add(c, acc.0[at + k]);
        }
        acc
    }

    /// `acc + ∂v`, `∂v` in groups `at..at + Q` of `acc`.
    #[inline(always)]
    #[must_use]
    pub fn add_into<const W: usize>(self, mut acc: Tangent<G, W>, at: usize) -> Tangent<G, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = acc.0[at + k].add(x);
        }
        acc
    }

    /// `acc - ∂v`, `∂v` in groups `at..at + Q` of `acc`.
    #[inline(always)]
    #[must_use]
    pub fn sub_from<const W: usize>(self, mut acc: Tangent<G, W>, at: usize) -> Tangent<G, W> {
        for (k, x) in self.0.into_iter().enumerate() {
            acc.0[at + k] = acc.0[at + k].sub(x);
        }
        acc
    }
}

impl<G: Group, const Q: usize> Add for Tangent<G, Q> {
    type Output = Self;
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        Tangent(core::array::from_fn(|k| self.0[k].add(other.0[k])))
    }
}

impl<G: Group, const Q: usize> Sub for Tangent<G, Q> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        Tangent(core::array::from_fn(|k| self.0[k].sub(other.0[k])))
    }
}

impl<G: Group, const Q: usize> Neg for Tangent<G, Q> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Tangent(self.0.map(Group::neg))
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
        let wide: Tangent<[T; 8], 3> = Tangent([y, y, y]);
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

    /// In groups of four, as in eight: each step the scalar one, lane by lane, and a row read
    /// off four directions a group.
    fn agrees_in_fours<T: Real>() {
        let (x, y, c) = (lanes::<T>(0.0), lanes::<T>(3.5), T::from_f64(-0.713));
        let four = |v: [T; 8], at: usize| -> [T; 4] { core::array::from_fn(|l| v[l + at]) };
        let (a, b) = (
            Tangent([four(x, 0), four(x, 4)]),
            Tangent([four(y, 0), four(y, 4)]),
        );
        for l in 0..8 {
            let (g, i) = (l / 4, l % 4);
            assert_eq!(a.mul_add(c, b).0[g][i], x[l].mul_add(c, y[l]));
            assert_eq!(a.scale(c).0[g][i], x[l] * c);
            assert_eq!((a + b).0[g][i], x[l] + y[l]);
            assert_eq!((a - b).0[g][i], x[l] - y[l]);
            assert_eq!((-a).0[g][i], -x[l]);
        }
        let row: [T; 7] = a.row();
        assert_eq!(row[..], x[..7]);
        // Kept in groups 1 and 2 of four: directions 4..12 of a row of 14.
        let row: [T; 14] = a.row_at(1);
        assert!(row[..4].iter().chain(&row[12..]).all(|&v| v == T::ZERO));
        assert_eq!(row[4..12], x[..]);
        let wide: Tangent<[T; 4], 3> = a.widen(1);
        assert_eq!(wide.0, [[T::ZERO; 4], four(x, 0), four(x, 4)]);
        let sum = b.mul_add_into(c, wide, 1);
        assert_eq!(sum.0[0], [T::ZERO; 4]);
        for l in 0..8 {
            assert_eq!(sum.0[1 + l / 4][l % 4], y[l].mul_add(c, x[l]));
        }
    }

    #[test]
    fn steps_in_fours_are_the_scalar_operations_lane_by_lane() {
        agrees_in_fours::<f64>();
        agrees_in_fours::<f32>();
        agrees_in_fours::<crate::lanes::F64x4>();
    }

    #[test]
    fn steps_are_the_scalar_operations_lane_by_lane() {
        agrees::<f64>();
        agrees::<f32>();
        agrees::<crate::lanes::F64x4>();
    }
}
