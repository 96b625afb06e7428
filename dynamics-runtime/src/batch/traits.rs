//! The batch traits, from the method table's rows (`methods.rs`): for each of the runtime's
//! traits, one of `_batch` methods, implemented for every type that implements the first.

use super::{
    check_count, check_output, drive, lanes, BatchScalar, DerivativesBatchScalar, States, StatesMut,
};
// The result table's types name these.
use crate::{ForwardDynamicsDerivatives, InverseDynamicsDerivatives, NotPositiveDefinite, Pose};

/// The traits from the table's rows: a method with a `batch` name gets its `_batch` form.
macro_rules! declare_batch {
    ($(
        $(#[doc = $_trait_doc:literal])*
        trait $trait:ident<$config:ident $(, $space:ident)* $(; $($count:ident $(= $count_default:ident)?),+)?> $(: $_supertrait:ident<$($_super_argument:ident),+>)?, nalgebra $_nalgebra:ident, batch $batch:ident {
            items { $($_items:tt)* }
            $(
                $(#[doc = $_family_doc:literal])*
                family $_family:ident { $($_family_row:tt)* }
                methods {$(
                    $(#[doc = $_doc:literal])*
                    fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $_wrapper:ident $(, batch $batch_fn:ident)? {
                        $($_row:tt)*
                    }
                )*}
            )*
        }
    )*) => {$(
        #[doc = concat!("The [`", stringify!($trait), "`](crate::", stringify!($trait), ") methods over many states ")]
        #[doc = "([`batch`](crate::batch)), implemented for every type that implements it."]
        pub trait $batch<const $config: usize $(, const $space: usize)* $($(, const $count: usize $(= $count_default)?)+)?>: crate::$trait<$config $(, $space)* $($(, $count)+)?> {
            $($(
                batch_method!($trait $config fn $name($($argument),*) -> $result; $($batch_fn)?);
            )*)*
        }

        impl<R: crate::$trait<$config $(, $space)* $($(, $count)+)?> + ?Sized, const $config: usize $(, const $space: usize)* $($(, const $count: usize)+)?>
            $batch<$config $(, $space)* $($(, $count)+)?> for R {}
    )*};
}

/// The `_batch` form of one method, if its row names one: the derivatives' states in the lanes
/// of [`DerivativesBatchScalar`], the others' in those of [`BatchScalar`].
macro_rules! batch_method {
    ($trait:ident $config:ident fn $name:ident($($argument:ident),*) -> $result:ident;) => {};
    ($trait:ident $config:ident fn $name:ident($($argument:ident),*) -> inverse_derivatives; $batch:ident) => {
        batch_method!(@ DerivativesBatchScalar $trait $config fn $name($($argument),*) -> inverse_derivatives; $batch);
    };
    ($trait:ident $config:ident fn $name:ident($($argument:ident),*) -> forward_derivatives; $batch:ident) => {
        batch_method!(@ DerivativesBatchScalar $trait $config fn $name($($argument),*) -> forward_derivatives; $batch);
    };
    ($trait:ident $config:ident fn $name:ident($($argument:ident),*) -> $result:ident; $batch:ident) => {
        batch_method!(@ BatchScalar $trait $config fn $name($($argument),*) -> $result; $batch);
    };
    (@ $scalar:ident $trait:ident $config:ident fn $name:ident($($argument:ident),*) -> $result:ident; $batch:ident) => {
        #[doc = concat!("[`", stringify!($trait), "::", stringify!($name), "`](crate::", stringify!($trait), "::", stringify!($name), ") of every state, into `out`: ")]
        #[doc = "[`batch`](crate::batch) has the layouts and what a failed solve writes."]
        ///
        /// # Panics
        ///
        /// If an input does not hold as many states as `out`, or the slices of one (one per
        /// joint) or of `out` differ in length.
        #[inline]
        #[track_caller]
        fn $batch<T: $scalar<L>, const L: usize>(
            &self,
            $($argument: &batch_input!($argument, T, $config),)*
            out: &mut (impl StatesMut<array_result!($result)> + ?Sized),
        ) {
            let len = out.count();
            check_output(len, out.ragged());
            $(check_count(stringify!($argument), $argument.count(), $argument.ragged(), len);)*
            drive::<_, _, L>(
                len,
                out,
                |k| self.$name::<T::Lanes>($(&lanes::<T::Lanes, _, L, _>($argument, k)),*),
                |k| self.$name::<T>($(&$argument.state(k)),*),
            );
        }
    };
}

/// The type of a method's input states: a wrench has six values, the configuration `C` (the
/// trait's first const parameter), the other joint variables `N`.
macro_rules! batch_input {
    (q, $t:ident, $config:ident) => { (impl States<$t, $config> + ?Sized) };
    (wrench, $t:ident, $config:ident) => { (impl States<$t, 6> + ?Sized) };
    ($joint:ident, $t:ident, $config:ident) => { (impl States<$t, N> + ?Sized) };
}

for_each_method!(declare_batch);
