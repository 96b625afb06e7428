//! The traits that `#[derive(Dynamics)]` implements, declared from the method table
//! (`methods.rs`): `τ = M(q) q̈ + C(q, q̇) q̇ + g(q)` (Niku eq. 6.46) and its parts in
//! [`Dynamics`], and, for a robot that asks for them, their derivatives in
//! [`DynamicsDerivatives`].

use crate::{
    ForwardDynamicsDerivatives, InverseDynamicsDerivatives, NotPositiveDefinite, Pose, Real,
};

/// The trait from the method table's rows: one method per row, its arguments `&[T; N]`.
macro_rules! declare_dynamics {
    ($(
        $(#[doc = $doc:literal])*
        fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $_wrapper:ident {
            variant: $_variant:ident,
            family: $family:ident,
            equation: $_equation:expr,
            prefix: $_prefix:literal,
            summary: $_summary:literal,
            element: $_element:literal,
            $(diagonal: $_diagonal:literal,)?
            $(default: $default:ident,)?
        }
    )*) => {
        /// Closed-form equations of motion of a serial robot with `N` joints,
        /// `tau = M(q) qdd + C(q, qd) qd + g(q)` (Niku eq. 6.46).
        ///
        /// Every method is straight-line code generated from the robot's D-H table: no loops, no
        /// heap. Each is generic over the scalar, so one robot evaluates in `f32` or `f64`; the
        /// robot's parameters (struct fields) are converted to that scalar on each call.
        pub trait Dynamics<const N: usize> {
            /// Number of joints.
            const DOF: usize = N;
            $(
                in_trait!(Dynamics, $family, trait_method!(
                    $(#[doc = $doc])*
                    fn $name<T: Real>(&self, $($argument: argument_type!($argument, T, N)),*) -> array_result!($result, T, N);
                    $($default)?
                ););
            )*
        }

        /// The derivatives of the equations of motion, for model-predictive and optimal
        /// control: implemented by `#[derive(Dynamics)]` for a robot that asks for them with
        /// `#[dynamics(..., derivatives = true)]`, since their code is several times the size
        /// of the rest, and a robot that does not call them should not compile them.
        ///
        /// Straight-line code from the same expression graph as [`Dynamics`]: the derivatives
        /// of its traced `τ` (forward differentiation at compile time, no finite differences,
        /// no automatic differentiation at run time), and `∂q̈/∂x = −M⁻¹ ∂τ/∂x` solved with the
        /// LDLᵀ of `M` (Carpentier and Mansard, RSS 2018).
        pub trait DynamicsDerivatives<const N: usize>: Dynamics<N> {
            $(
                in_trait!(DynamicsDerivatives, $family, trait_method!(
                    $(#[doc = $doc])*
                    fn $name<T: Real>(&self, $($argument: argument_type!($argument, T, N)),*) -> array_result!($result, T, N);
                    $($default)?
                ););
            )*
        }
    };
}

/// A row's items, kept in the trait of its family: the `derivatives` family's methods are
/// [`DynamicsDerivatives`]'s, every other family's [`Dynamics`]'s.
macro_rules! in_trait {
    (Dynamics, derivatives, $($item:tt)*) => {};
    (Dynamics, $family:ident, $($item:tt)*) => { $($item)* };
    (DynamicsDerivatives, derivatives, $($item:tt)*) => { $($item)* };
    (DynamicsDerivatives, $family:ident, $($item:tt)*) => {};
}

/// A trait method's declaration, with a body where the row gives a default (`zeros`: the
/// method of a term a robot may not have, such as friction).
macro_rules! trait_method {
    ($(#[$doc:meta])* fn $name:ident<T: Real>(&self, $($argument:ident: $ty:ty),*) -> $ret:ty;) => {
        $(#[$doc])*
        fn $name<T: Real>(&self, $($argument: $ty),*) -> $ret;
    };
    ($(#[$doc:meta])* fn $name:ident<T: Real>(&self, $($argument:ident: $ty:ty),*) -> $ret:ty; zeros) => {
        $(#[$doc])*
        #[inline]
        fn $name<T: Real>(&self, $($argument: $ty),*) -> $ret {
            $(let _ = $argument;)*
            [T::ZERO; N]
        }
    };
}

/// The type of a method's argument: `&[T; N]` for the joint variables, `&[T; 6]` for a wrench
/// `[fx, fy, fz, mx, my, mz]`.
macro_rules! argument_type {
    (wrench, $t:ty, $n:ident) => {
        &[$t; 6]
    };
    ($joint:ident, $t:ty, $n:ident) => {
        &[$t; $n]
    };
}

/// The type of a method's result: `[[T; N]; N]`, `[T; N]` or `T`; a [`Pose`], one per link,
/// a Jacobian's six rows `[[T; N]; 6]` or a spatial 6-vector `[T; 6]`; a matrix or vector
/// solved with `M`, or [`NotPositiveDefinite`]; the derivatives' structs.
macro_rules! array_result {
    (pose, $t:ty, $n:ident) => {
        Pose<$t>
    };
    (poses, $t:ty, $n:ident) => {
        [Pose<$t>; $n]
    };
    (jacobian, $t:ty, $n:ident) => {
        [[$t; $n]; 6]
    };
    (spatial, $t:ty, $n:ident) => {
        [$t; 6]
    };
    (matrix, $t:ty, $n:ident) => {
        [[$t; $n]; $n]
    };
    (vector, $t:ty, $n:ident) => {
        [$t; $n]
    };
    (scalar, $t:ty, $n:ident) => {
        $t
    };
    (solved_matrix, $t:ty, $n:ident) => {
        Result<[[$t; $n]; $n], NotPositiveDefinite>
    };
    (solved_vector, $t:ty, $n:ident) => {
        Result<[$t; $n], NotPositiveDefinite>
    };
    (inverse_derivatives, $t:ty, $n:ident) => {
        InverseDynamicsDerivatives<[[$t; $n]; $n]>
    };
    (forward_derivatives, $t:ty, $n:ident) => {
        Result<ForwardDynamicsDerivatives<[$t; $n], [[$t; $n]; $n]>, NotPositiveDefinite>
    };
}

for_each_method!(declare_dynamics);
