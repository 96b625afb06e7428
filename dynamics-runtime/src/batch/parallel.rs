//! Batches split across threads (the `rayon` feature): `InParallel(&robot)` has every `_batch`
//! method of the batch traits, with the same arguments and results, which cuts the states into
//! chunks of whole lane groups and evaluates the chunks on rayon's thread pool, each as the
//! sequential `_batch` method does. Each state's result is the same bits either way: a state is
//! in the same lanes of the same group (groups start at multiples of the lane count in both).
//!
//! A batch of up to [`MIN_CHUNK`] states runs on the calling thread: waking the pool's threads
//! costs more than they save on it.

use super::{
    check_count, check_output, drive, lanes, BatchScalar, DerivativesBatchScalar, States, StatesMut,
};
use rayon::prelude::*;
use std::vec::Vec;
// The result table's types name these.
use crate::{ForwardDynamicsDerivatives, InverseDynamicsDerivatives, NotPositiveDefinite, Pose};

/// The smallest chunk handed to a thread, in states: enough work (about 15 µs on the cheapest
/// methods) to pay for waking a pool thread, which took longer than 128 states of τ.
const MIN_CHUNK: usize = 1024;

/// A robot whose `_batch` methods run on rayon's threads:
/// `InParallel(&robot).inverse_dynamics_batch(&q, &qd, &qdd, &mut tau)`.
#[derive(Clone, Copy, Debug)]
pub struct InParallel<'a, R: ?Sized>(pub &'a R);

/// Results that can be cut into disjoint chunks of consecutive states, one per thread: a slice
/// of results, or one slice per joint.
pub trait ChunksMut<O>: StatesMut<O> {
    /// One chunk.
    type Chunk<'a>: StatesMut<O> + Send
    where
        Self: 'a;
    /// The results cut into chunks of `size` states (the last one shorter).
    fn chunks(&mut self, size: usize) -> Vec<Self::Chunk<'_>>;
}

impl<O: Send> ChunksMut<O> for [O] {
    type Chunk<'a>
        = &'a mut [O]
    where
        O: 'a;
    fn chunks(&mut self, size: usize) -> Vec<&mut [O]> {
        self.chunks_mut(size).collect()
    }
}

impl<O: Send, const K: usize> ChunksMut<O> for [O; K] {
    type Chunk<'a>
        = &'a mut [O]
    where
        O: 'a;
    fn chunks(&mut self, size: usize) -> Vec<&mut [O]> {
        self.as_mut_slice().chunks(size)
    }
}

impl<T: Send, const M: usize> ChunksMut<[T; M]> for [&mut [T]; M] {
    type Chunk<'a>
        = [&'a mut [T]; M]
    where
        Self: 'a;
    fn chunks(&mut self, size: usize) -> Vec<[&mut [T]; M]> {
        let count = self.first().map_or(0, |c| c.len()).div_ceil(size.max(1));
        let mut columns = self.each_mut().map(|column| column.chunks_mut(size));
        (0..count)
            .map(|_| {
                columns
                    .each_mut()
                    .map(|c| c.next().expect("as long as the first"))
            })
            .collect()
    }
}

/// As [`drive`], the states cut into chunks of whole groups of `L` run on rayon's threads.
#[doc(hidden)]
#[inline]
pub fn drive_parallel<X, O, const L: usize>(
    len: usize,
    out: &mut (impl ChunksMut<O> + ?Sized),
    group: impl Fn(usize) -> X + Sync,
    one: impl Fn(usize) -> O + Sync,
) where
    X: super::SplitLanes<L, Single = O>,
{
    let size = chunk_size::<L>(len, rayon::current_num_threads());
    if size >= len {
        return drive::<X, O, L>(len, out, group, one);
    }
    out.chunks(size)
        .into_par_iter()
        .enumerate()
        .for_each(|(c, mut chunk)| {
            let start = c * size;
            drive::<X, O, L>(
                chunk.count(),
                &mut chunk,
                |k| group(start + k),
                |k| one(start + k),
            );
        });
}

/// Four chunks per thread, for balance, of at least [`MIN_CHUNK`] states, each a whole number
/// of groups of `L`.
fn chunk_size<const L: usize>(len: usize, threads: usize) -> usize {
    let size = len.div_ceil(4 * threads.max(1)).max(MIN_CHUNK);
    size.div_ceil(L) * L
}

/// The `_batch` methods of every trait's rows on [`InParallel`].
macro_rules! declare_parallel {
    ($(
        $(#[doc = $_trait_doc:literal])*
        trait $trait:ident<$config:ident $(, $space:ident)* $(; $($count:ident $(= $_count_default:ident)?),+)?> $(: $_supertrait:ident<$($_super_argument:ident),+>)?, nalgebra $_nalgebra:ident, batch $_batch:ident {
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
        // The trait's generics as one token tree, which its methods' repetition can carry.
        parallel_impl!($trait [$config $($space)*] [$($($count)+)?] {$($(
            fn $name($($argument),*) -> $result $(, $batch_fn)?;
        )*)*});
    )*};
}

/// One trait's methods on [`InParallel`].
macro_rules! parallel_impl {
    // A floating base's (`FloatingDynamics<Q, N>`) has none yet: its methods' names are
    // `Dynamics`' and an inherent impl cannot hold both.
    ($trait:ident [$config:ident $space:ident] $generics:tt { $($_methods:tt)* }) => {};
    ($trait:ident [N] $generics:tt {$(
        fn $name:ident($($argument:ident),*) -> $result:ident $(, $batch:ident)?;
    )*}) => {
        impl<R: ?Sized + Sync> InParallel<'_, R> {$(
            parallel_method!($trait $generics fn $name($($argument),*) -> $result; $($batch)?);
        )*}
    };
}

/// The parallel form of one method, if its row names a `_batch` form: the derivatives' states
/// in the lanes of [`DerivativesBatchScalar`], the others' in those of [`BatchScalar`].
macro_rules! parallel_method {
    ($trait:ident $_generics:tt fn $name:ident($($argument:ident),*) -> $result:ident;) => {};
    ($trait:ident $generics:tt fn $name:ident($($argument:ident),*) -> inverse_derivatives; $batch:ident) => {
        parallel_method!(@ DerivativesBatchScalar $trait $generics fn $name($($argument),*) -> inverse_derivatives; $batch);
    };
    ($trait:ident $generics:tt fn $name:ident($($argument:ident),*) -> forward_derivatives; $batch:ident) => {
        parallel_method!(@ DerivativesBatchScalar $trait $generics fn $name($($argument),*) -> forward_derivatives; $batch);
    };
    ($trait:ident $generics:tt fn $name:ident($($argument:ident),*) -> $result:ident; $batch:ident) => {
        parallel_method!(@ BatchScalar $trait $generics fn $name($($argument),*) -> $result; $batch);
    };
    (@ $scalar:ident $trait:ident [$($count:ident)*] fn $name:ident($($argument:ident),*) -> $result:ident; $batch:ident) => {
        #[doc = concat!("[`", stringify!($trait), "Batch::", stringify!($batch), "`](crate::", stringify!($trait), "Batch::", stringify!($batch), ") ")]
        #[doc = "with the states cut into chunks on rayon's threads."]
        ///
        /// # Panics
        ///
        /// If an input does not hold as many states as `out`, or the slices of one (one per
        /// joint) or of `out` differ in length.
        #[inline]
        #[track_caller]
        pub fn $batch<T, const L: usize, const N: usize $(, const $count: usize)*>(
            &self,
            $($argument: &parallel_input!($argument, T),)*
            out: &mut (impl ChunksMut<array_result!($result)> + ?Sized),
        ) where
            R: crate::$trait<N $(, $count)*>,
            T: $scalar<L> + Sync,
        {
            let robot = self.0;
            let len = out.count();
            check_output(len, out.ragged());
            $(check_count(stringify!($argument), $argument.count(), $argument.ragged(), len);)*
            drive_parallel::<_, _, L>(
                len,
                out,
                |k| robot.$name::<T::Lanes>($(&lanes::<T::Lanes, _, L, _>($argument, k)),*),
                |k| robot.$name::<T>($(&$argument.state(k)),*),
            );
        }
    };
}

/// The type of a method's input states, shared by the threads.
macro_rules! parallel_input {
    (wrench, $t:ident) => { (impl States<$t, 6> + Sync + ?Sized) };
    ($joint:ident, $t:ident) => { (impl States<$t, N> + Sync + ?Sized) };
}

for_each_method!(declare_parallel);

#[cfg(test)]
mod tests {
    use super::chunk_size;

    #[test]
    fn chunks_are_whole_groups_and_not_too_small() {
        assert_eq!(chunk_size::<4>(100, 2), 1_024);
        assert_eq!(chunk_size::<4>(20_000, 2), 2_500);
        assert_eq!(chunk_size::<8>(20_001, 2), 2_504);
        assert_eq!(chunk_size::<4>(10_000, 0), 2_500);
    }
}
