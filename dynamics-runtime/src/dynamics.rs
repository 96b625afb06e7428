//! The traits that `#[derive(Dynamics)]` implements, declared from the method table
//! (`methods.rs`): `τ = M(q) q̈ + C(q, q̇) q̇ + g(q)` (Niku eq. 6.46) and its parts in
//! [`Dynamics`], and, for a robot that asks for them, their derivatives in
//! [`DynamicsDerivatives`].

// The result table's types name these.
use crate::{
    ForwardDynamicsDerivatives, InverseDynamicsDerivatives, NotPositiveDefinite, Pose, Real,
};

/// `array_result!(keyword)`, `nalgebra_result!(keyword)` (result types) and
/// `to_nalgebra!(keyword, value)` (the conversion) from the table's rows, for the traits'
/// declarations.
macro_rules! declare_result_lookups {
    ($d:tt $(
        $(#[doc = $_doc:literal])*
        $keyword:ident {
            variant: $_variant:ident,
            array: $array:ty,
            nalgebra: $nalgebra:ty,
            to_nalgebra: $to_nalgebra:expr,
            rows: $_rows:ty,
            from_rows: $_from_rows:expr,
        }
    )*) => {
        /// The trait method's result type of a row's keyword.
        macro_rules! array_result {
            $(($keyword) => { $array };)*
        }

        /// The `_na` wrapper's result type of a row's keyword (read with the `nalgebra` feature).
        #[allow(unused_macros)]
        macro_rules! nalgebra_result {
            $(($keyword) => { $nalgebra };)*
        }

        /// An array result turned into its nalgebra form (read with the `nalgebra` feature,
        /// whose `convert` gives the row's closure its argument's type).
        #[allow(unused_macros)]
        macro_rules! to_nalgebra {
            $(($keyword, $d value:expr) => { convert($d value, $to_nalgebra) };)*
        }
    };
}

for_each_result!(declare_result_lookups $);

/// The traits from the method table's rows: one trait per `trait` row, one method per `fn`
/// row of its families, its arguments `&[T; N]`.
macro_rules! declare_traits {
    ($(
        $(#[doc = $trait_doc:literal])*
        trait $trait:ident<$config:ident $(, $space:ident)* $(; $($count:ident $(= $count_default:ident)?),+)?> $(: $supertrait:ident<$($super_argument:ident),+>)?, nalgebra $_nalgebra:ident, batch $_batch:ident {
            items { $($items:tt)* }
            $(
                $(#[doc = $_family_doc:literal])*
                family $_family:ident { $($_family_row:tt)* }
                methods {$(
                    $(#[doc = $doc:literal])*
                    fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $_wrapper:ident $(, batch $_batch_fn:ident)? {
                        variant: $_variant:ident,
                        equation: $_equation:expr,
                        prefix: $_prefix:literal,
                        summary: $_summary:literal,
                        element: $_element:literal,
                        $(diagonal: $_diagonal:literal,)?
                        $(default: $default:ident,)?
                        $(compiled_apart: $_apart:literal,)?
                        $(into: $into:ident,)?
                    }
                )*}
            )*
        }
    )*) => {$(
        $(#[doc = $trait_doc])*
        pub trait $trait<const $config: usize $(, const $space: usize)* $($(, const $count: usize $(= $count_default)?)+)?> $(: $supertrait<$($super_argument),+>)? {
            $($items)*
            $($(
                trait_method!(
                    $(#[doc = $doc])*
                    fn $name<T: Real>(&self, $($argument: argument_type!($argument, T, $config)),*) -> array_result!($result);
                    $($default)?
                );
                into_method!(
                    fn $name<T: Real>(&self, $($argument: argument_type!($argument, T, $config)),*) -> array_result!($result);
                    $($into)?
                );
            )*)*
        }
    )*};
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

/// For a row with `into`, the method writing `$name`'s result into `out`, provided as a call of
/// `$name` (the derive implements it: each element stored where it is computed, for the results too large to be
/// returned through registers).
macro_rules! into_method {
    (fn $name:ident<T: Real>(&self, $($argument:ident: $ty:ty),*) -> $ret:ty;) => {};
    (fn $name:ident<T: Real>(&self, $($argument:ident: $ty:ty),*) -> $ret:ty; $into:ident) => {
        #[doc = concat!("[`", stringify!($name), "`](Self::", stringify!($name), ") written into `out`:")]
        /// the same values, each stored where it is computed rather than returned together (the
        /// faster of the two: hundreds of values do not fit in the registers and would wait on
        /// the stack for the copy). For stacking samples into the rows of an identification
        /// problem without a copy. The elements that are zero at every state need not be
        /// stored: a tree's `mass_matrix_into` leaves the blocks between its branches as `out`
        /// has them, so `out` must hold zeros there (zeros, or an earlier result of the robot).
        #[inline]
        fn $into<T: Real>(&self, $($argument: $ty,)* out: &mut $ret) {
            *out = self.$name($($argument),*);
        }
    };
}

/// The type of a method's argument: `&[T; C]` for the configuration `q`, `C` the trait's first
/// const parameter (`N` on a fixed base, `Q` on a floating one), `&[T; N]` for the other joint
/// variables (the velocity's length), `&[T; 6]` for a wrench `[fx, fy, fz, mx, my, mz]`,
/// `&[[T; 6]; TIPS]` for a wrench at each tip (`TipKinematics`' count).
macro_rules! argument_type {
    (q, $t:ty, $config:ident) => {
        &[$t; $config]
    };
    (wrench, $t:ty, $config:ident) => {
        &[$t; 6]
    };
    (wrenches, $t:ty, $config:ident) => {
        &[[$t; 6]; TIPS]
    };
    ($joint:ident, $t:ty, $config:ident) => {
        &[$t; N]
    };
}

for_each_method!(declare_traits);
