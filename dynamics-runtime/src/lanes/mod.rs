//! Several states in one call: [`Real`] scalars made of vector lanes, one state per lane.
//!
//! Every generated method is generic over `T: Real`, so it runs on these types as it runs on
//! `f64`: `robot.inverse_dynamics(&q, &qd, &qdd)` with `q: [F64x4; N]` evaluates four states
//! at once, lane `l` of every input being state `l`. The generated code is the same; each of
//! its operations is one vector instruction instead of one scalar instruction.
//!
//! | type | lanes | x86-64 with AVX2 | x86-64 without | elsewhere |
//! |---|---|---|---|---|
//! | [`F64x4`] | 4 × `f64` | one AVX register | two SSE2 registers | four `f64` |
//! | [`F64x8`] | 8 × `f64` | one AVX-512 register (AVX-512F and the `avx512` feature), else two AVX registers | four SSE2 registers | eight `f64` |
//! | [`F64x2`] | 2 × `f64` | one SSE2 register | one SSE2 register | two `f64` |
//! | [`F32x8`] | 8 × `f32` | one AVX register | two SSE registers | eight `f32` |
//! | [`F32x4`] | 4 × `f32` | one SSE register | one SSE register | four `f32` |
//!
//! "AVX2" is the build's (`-C target-cpu=native` on most machines, or `-C target-feature=+avx2`):
//! the choice is made when the crate is compiled, not at run time. The portable form (plain
//! arrays, lane by lane) is what other targets get, for the compiler to vectorize where it can
//! (NEON on aarch64: not written by hand, nor measured).
//!
//! **Bit for bit.** Each lane gives exactly what the same method gives in `f64` (or `f32`) for
//! that lane's state: the operations are the same IEEE operations in the same order.
//! `mul_add` is fused in the lanes exactly where it is fused for the scalar (the `std` feature
//! and FMA in the build), sines and cosines come from the same kernels as the scalar's
//! (lanes outside their fast range one by one, as the scalar), `sign` and `tanh` lane by
//! lane. A NaN is NaN in both, but its sign and payload may differ: an operation on two NaNs
//! gives the first operand's on x86, and the compiler orders the operands of sums and products
//! as suits its registers (Rust leaves a NaN result's sign unspecified), differently in the
//! lanes' code and the scalar's, and even at two call sites of the same scalar method.
//!
//! **Failure on lanes.** The methods that solve with the mass matrix (`forward_dynamics`,
//! `mass_matrix_inverse`, `forward_dynamics_derivatives`) test the pivots of its LDLᵀ with
//! [`Real::all_positive`]: on lanes, `Err(NotPositiveDefinite)` means that *at least one*
//! lane's mass matrix is not positive definite, and gives no values for the others. Evaluate
//! the states of that group one at a time (in `f64`) to know which failed.
//!
//! [`gather`] builds the lanes from states and [`SplitLanes::split_lanes`] takes any result
//! (a number, arrays of them, a [`Pose`](crate::Pose), the derivatives' structs) apart into one
//! result per state.

#[cfg(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512"))]
#[allow(unsafe_code)]
mod avx512;
#[allow(unsafe_code)]
pub(crate) mod oct;
#[cfg(any(test, not(target_arch = "x86_64")))]
mod portable;
mod split;
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
mod x86;

pub use split::{gather, SplitLanes};

use crate::real::{Real, RealScalar};

/// A [`Real`] of `L` lanes of the scalar [`Lanes::Scalar`].
pub trait Lanes<const L: usize>: Real {
    /// The scalar of one lane.
    type Scalar: RealScalar;
    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// The lanes, first to last.
    fn from_array(lanes: [Self::Scalar; L]) -> Self;
    /// The lanes as an array.
    fn to_array(self) -> [Self::Scalar; L];
    /// `L` values transposed: lane `l` of value `j` of the result is lane `j` of value `l` (the
    /// rows of `L` states into the lanes of `L` values, and back). In registers where the
    /// backend has the shuffles (`F64x4` with AVX2), else through arrays.
    #[inline(always)]
    fn transpose(values: [Self; L]) -> [Self; L] {
        let rows = values.map(Self::to_array);
        core::array::from_fn(|j| Self::from_array(core::array::from_fn(|l| rows[l][j])))
    }
}

/// The lane type `$name` of `$lanes` × `$e` on the backend module `$b`, which gives its
/// register type `V` and its operations.
macro_rules! lane_type {
    (
        $(#[doc = $doc:literal])* $name:ident, $e:ident, $lanes:literal, $b:ident
        $(, transpose: $transpose:path)?
    ) => {
        $(#[doc = $doc])*
        #[derive(Clone, Copy)]
        #[repr(transparent)]
        pub struct $name($b::V);

        impl $name {
            /// Every lane `x`.
            #[inline(always)]
            #[must_use]
            pub fn splat(x: $e) -> Self {
                Self($b::splat(x))
            }
            /// The lanes, first to last.
            #[inline(always)]
            #[must_use]
            pub fn from_array(lanes: [$e; $lanes]) -> Self {
                Self($b::from_array(lanes))
            }
            /// The lanes as an array.
            #[inline(always)]
            #[must_use]
            pub fn to_array(self) -> [$e; $lanes] {
                $b::to_array(self.0)
            }
        }

        impl Lanes<$lanes> for $name {
            type Scalar = $e;
            #[inline(always)]
            fn splat(x: $e) -> Self {
                Self::splat(x)
            }
            #[inline(always)]
            fn from_array(lanes: [$e; $lanes]) -> Self {
                Self::from_array(lanes)
            }
            #[inline(always)]
            fn to_array(self) -> [$e; $lanes] {
                self.to_array()
            }
            $(
                #[inline(always)]
                fn transpose(values: [Self; $lanes]) -> [Self; $lanes] {
                    $transpose(values.map(|v| v.0)).map(Self)
                }
            )?
        }

        impl From<[$e; $lanes]> for $name {
            #[inline(always)]
            fn from(lanes: [$e; $lanes]) -> Self {
                Self::from_array(lanes)
            }
        }

        impl From<$name> for [$e; $lanes] {
            #[inline(always)]
            fn from(v: $name) -> Self {
                v.to_array()
            }
        }

        impl Default for $name {
            #[inline(always)]
            fn default() -> Self {
                <Self as Real>::ZERO
            }
        }

        impl core::fmt::Debug for $name {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_tuple(stringify!($name)).field(&self.to_array()).finish()
            }
        }

        /// Every lane equal (IEEE: a NaN lane is equal to nothing).
        impl PartialEq for $name {
            #[inline(always)]
            fn eq(&self, other: &Self) -> bool {
                $b::all_eq(self.0, other.0)
            }
        }

        lane_operators!($name, $b);

        impl Real for $name {
            // The derivatives' columns one by one: a tangent of eight lanes of states would
            // take eight registers (the Panda's ∂τ 1,259 ns a state against 206 to 606).
            const TANGENTS_IN_LANES: bool = false;
            const ZERO: Self = Self($b::constant([0.0; $lanes]));
            const ONE: Self = Self($b::constant([1.0; $lanes]));
            #[inline(always)]
            fn from_f64(value: f64) -> Self {
                Self::splat(<$e as Real>::from_f64(value))
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                let (s, c) = $b::sin_cos(self.0);
                (Self(s), Self(c))
            }
            #[inline(always)]
            fn sin(self) -> Self {
                self.sin_cos().0
            }
            #[inline(always)]
            fn cos(self) -> Self {
                self.sin_cos().1
            }
            #[inline(always)]
            fn mul_add(self, a: Self, b: Self) -> Self {
                Self($b::mul_add(self.0, a.0, b.0))
            }
            #[inline(always)]
            fn sin_cos_4(x: [Self; 4]) -> ([Self; 4], [Self; 4]) {
                let both = x.map(Self::sin_cos);
                (both.map(|p| p.0), both.map(|p| p.1))
            }
            #[inline(always)]
            fn sin_cos_8(x: [Self; 8]) -> ([Self; 8], [Self; 8]) {
                let both = x.map(Self::sin_cos);
                (both.map(|p| p.0), both.map(|p| p.1))
            }
            #[inline(always)]
            fn sign(self) -> Self {
                Self($b::sign(self.0))
            }
            #[inline(always)]
            fn tanh(self) -> Self {
                Self::from_array(self.to_array().map(<$e as Real>::tanh))
            }
            #[inline(always)]
            fn all_positive(&self) -> bool {
                $b::all_positive(self.0)
            }
        }
    };
}

/// The arithmetic operators of a lane type, lane by lane.
macro_rules! lane_operators {
    ($name:ident, $b:ident) => {
        lane_operators!(@binary $name, $b, Add add AddAssign add_assign);
        lane_operators!(@binary $name, $b, Sub sub SubAssign sub_assign);
        lane_operators!(@binary $name, $b, Mul mul MulAssign mul_assign);
        impl core::ops::Div for $name {
            type Output = Self;
            #[inline(always)]
            fn div(self, other: Self) -> Self {
                Self($b::div(self.0, other.0))
            }
        }
        impl core::ops::Neg for $name {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                Self($b::neg(self.0))
            }
        }
    };
    (@binary $name:ident, $b:ident, $op:ident $f:ident $assign:ident $f_assign:ident) => {
        impl core::ops::$op for $name {
            type Output = Self;
            #[inline(always)]
            fn $f(self, other: Self) -> Self {
                Self($b::$f(self.0, other.0))
            }
        }
        impl core::ops::$assign for $name {
            #[inline(always)]
            fn $f_assign(&mut self, other: Self) {
                *self = core::ops::$op::$f(*self, other);
            }
        }
    };
}

/// The types, each in a module of its own for its backend's `V`.
mod f64x4 {
    use super::{Lanes, Real};
    lane_type!(
        /// Four `f64` lanes: one AVX register where the build has AVX2, else two SSE2
        /// registers on x86-64, four `f64` elsewhere.
        /// See [the module](crate::lanes).
        F64x4,
        f64,
        4,
        backend,
        transpose: transpose
    );
    /// Four registers transposed by AVX's shuffles.
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    use super::x86::transpose_f64x4 as transpose;
    /// Four registers transposed through arrays.
    #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
    #[inline(always)]
    fn transpose(values: [backend::V; 4]) -> [backend::V; 4] {
        let rows = values.map(backend::to_array);
        core::array::from_fn(|j| backend::from_array(core::array::from_fn(|l| rows[l][j])))
    }
    #[cfg(not(target_arch = "x86_64"))]
    use super::portable::f64x4 as backend;
    #[cfg(target_arch = "x86_64")]
    use super::x86::f64x4 as backend;
}

mod f64x8 {
    use super::{Lanes, Real};
    lane_type!(
        /// Eight `f64` lanes: one AVX-512 register where the build has AVX-512F and the
        /// `avx512` feature is on, else two AVX registers (AVX2) or four SSE2 registers on
        /// x86-64, eight `f64` elsewhere.
        /// See [the module](crate::lanes).
        F64x8,
        f64,
        8,
        backend,
        transpose: transpose
    );
    #[cfg(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512"))]
    use super::avx512::f64x8 as backend;
    /// Eight registers transposed by AVX-512's shuffles.
    #[cfg(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512"))]
    use super::avx512::f64x8::transpose;
    /// Eight registers transposed through arrays.
    #[cfg(not(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512")))]
    #[inline(always)]
    fn transpose(values: [backend::V; 8]) -> [backend::V; 8] {
        let rows = values.map(backend::to_array);
        core::array::from_fn(|j| backend::from_array(core::array::from_fn(|l| rows[l][j])))
    }
    #[cfg(not(target_arch = "x86_64"))]
    use super::portable::f64x8 as backend;
    #[cfg(all(
        target_arch = "x86_64",
        not(all(target_feature = "avx512f", feature = "avx512"))
    ))]
    use super::x86::f64x8 as backend;
}

mod f64x2 {
    use super::{Lanes, Real};
    lane_type!(
        /// Two `f64` lanes: one SSE2 register on x86-64, else two `f64`. See
        /// [the module](crate::lanes).
        F64x2,
        f64,
        2,
        backend
    );
    #[cfg(not(target_arch = "x86_64"))]
    use super::portable::f64x2 as backend;
    #[cfg(target_arch = "x86_64")]
    use super::x86::f64x2 as backend;
}

mod f32x8 {
    use super::{Lanes, Real};
    lane_type!(
        /// Eight `f32` lanes: one AVX register where the build has AVX2, else two SSE
        /// registers on x86-64, eight `f32` elsewhere.
        /// See [the module](crate::lanes).
        F32x8,
        f32,
        8,
        backend,
        transpose: transpose
    );
    /// Eight registers transposed by AVX's shuffles.
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    use super::x86::transpose_f32x8 as transpose;
    /// Eight registers transposed through arrays.
    #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
    #[inline(always)]
    fn transpose(values: [backend::V; 8]) -> [backend::V; 8] {
        let rows = values.map(backend::to_array);
        core::array::from_fn(|j| backend::from_array(core::array::from_fn(|l| rows[l][j])))
    }
    #[cfg(not(target_arch = "x86_64"))]
    use super::portable::f32x8 as backend;
    #[cfg(target_arch = "x86_64")]
    use super::x86::f32x8 as backend;
}

mod f32x4 {
    use super::{Lanes, Real};
    lane_type!(
        /// Four `f32` lanes: one SSE register on x86-64, else four `f32`. See
        /// [the module](crate::lanes).
        F32x4,
        f32,
        4,
        backend
    );
    #[cfg(not(target_arch = "x86_64"))]
    use super::portable::f32x4 as backend;
    #[cfg(target_arch = "x86_64")]
    use super::x86::f32x4 as backend;
}

pub use f32x4::F32x4;
pub use f32x8::F32x8;
pub use f64x2::F64x2;
pub use f64x4::F64x4;
pub use f64x8::F64x8;

#[cfg(test)]
mod tests;
