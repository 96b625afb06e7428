//! Many states in one call, for callers who do not want to think in lanes: every method of the
//! runtime's traits that takes joint values has a `_batch` form over slices of states
//! (`inverse_dynamics_batch(&q, &qd, &qdd, &mut tau)`), declared from the method table
//! (`methods.rs`) in one trait per trait: [`DynamicsBatch`], [`DynamicsDerivativesBatch`],
//! [`DynamicsRegressorBatch`], [`DynamicsBaseParametersBatch`], implemented for every robot;
//! the floating base's contacts, by hand, in [`FloatingContactsBatch`].
//!
//! The states are taken [`lanes`](crate::lanes) at a time — four for `f64` ([`F64x4`]), eight
//! for `f32` ([`F32x8`]); the derivatives' eight `f64` ([`F64x8`]) where the build computes
//! tangents in lanes ([`DerivativesBatchScalar`]): one call of the generated code on the lane type per group, each lane
//! giving bit for bit what one call gives for its state. A last, partial group repeats its last
//! state in the lanes it does not fill, and only the filled lanes are written. No heap.
//!
//! **Layouts.** Inputs are [`States`]: a slice of states (`&[[f64; N]]`, array of structs), or
//! one slice per joint (`[&[f64]; N]`, structure of arrays: `q[j][k]` is joint j of state k).
//! Outputs are [`StatesMut`]: a slice of results (`&mut [[f64; N]]`, `&mut [[[f64; N]; N]]`,
//! ...), or, for a result that is one value per joint, one slice per joint.
//!
//! **Failures.** A method that solves with the mass matrix writes `Err(NotPositiveDefinite)`
//! for exactly the states whose mass matrix is not positive definite: a group in which one lane
//! fails is evaluated again one state at a time.
//!
//! **NaN.** A state whose result has a NaN has a NaN in the same places in its batch's result,
//! but not always of the same sign: see [`lanes`](crate::lanes). (Evaluating such a group again
//! state by state would not give the sign of the caller's own call either: each call site of a
//! method is compiled apart.)
//!
//! **Threads.** With the `rayon` feature, `InParallel(&robot)` has the same `_batch`
//! methods, which cut the states into chunks of whole groups on rayon's thread pool: the same
//! bits as on one thread.
//!
//! # Panics
//!
//! If an input does not hold as many states as the output, or one slice per joint (of an input
//! or of the output) holds another number than its first: the message names the input and the
//! lengths.
//!
//! [`F64x4`]: crate::F64x4
//! [`F64x8`]: crate::F64x8
//! [`F32x8`]: crate::F32x8

mod contacts;
mod layout;
#[cfg(feature = "rayon")]
mod parallel;
mod traits;

pub use contacts::FloatingContactsBatch;
pub use layout::{States, StatesMut};
#[cfg(feature = "rayon")]
pub use parallel::{ChunksMut, InParallel};
pub use traits::{
    DynamicsBaseParametersBatch, DynamicsBatch, DynamicsDerivativesBatch, DynamicsRegressorBatch,
    DynamicsSimplifiedBatch, FloatingDynamicsBaseParametersBatch, FloatingDynamicsBatch,
    FloatingDynamicsDerivativesBatch, FloatingDynamicsRegressorBatch, TipKinematicsBatch,
};

use crate::lanes::{Lanes, SplitLanes};
use crate::real::RealScalar;

/// A scalar with the lane type its batches are evaluated in: `L` lanes of it.
pub trait BatchScalar<const L: usize>: RealScalar {
    /// `L` of these side by side, a [`Real`](crate::Real) of its own.
    type Lanes: Lanes<L, Scalar = Self> + SplitLanes<L, Single = Self>;
}

// Not `F64x8` where the build has AVX-512: on the Xeon measured, τ and M in batches ran no
// faster in eight lanes than in four (docs/performance.md), and the eight-lane gathers and
// transposes cost more for 6 or 7 joints. The derivatives do gain: `DerivativesBatchScalar`.
impl BatchScalar<4> for f64 {
    type Lanes = crate::F64x4;
}

impl BatchScalar<8> for f32 {
    type Lanes = crate::F32x8;
}

/// A scalar with the lane type the derivatives' batches are evaluated in, `L` of it: `f64` in
/// [`F64x8`](crate::F64x8) where the build computes tangents in lanes (AVX-512 and the `avx512`
/// feature), else as [`BatchScalar`]. Eight states in one AVX-512 register take the Panda's
/// derivatives column by column in two thirds to three quarters of the time a state of four
/// (`docs/performance.md`).
/// Unoptimized, the Panda's derivatives on `F64x8` take about 4 MB of stack, more than a
/// spawned thread's default 2 MB: a debug build batching them on such threads needs more.
pub trait DerivativesBatchScalar<const L: usize>: RealScalar {
    /// `L` of these side by side, a [`Real`](crate::Real) of its own.
    type Lanes: Lanes<L, Scalar = Self> + SplitLanes<L, Single = Self>;
}

#[cfg(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512"))]
impl DerivativesBatchScalar<8> for f64 {
    type Lanes = crate::F64x8;
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "avx512f", feature = "avx512")))]
impl DerivativesBatchScalar<4> for f64 {
    type Lanes = crate::F64x4;
}

impl DerivativesBatchScalar<8> for f32 {
    type Lanes = crate::F32x8;
}

/// The `M` values of states `k` to `k + L − 1` of `states` as lanes, the last state repeated
/// past the end.
#[doc(hidden)]
#[inline(always)]
pub fn lanes<V, S, const L: usize, const M: usize>(states: &S, k: usize) -> [V; M]
where
    V: Lanes<L>,
    S: States<V::Scalar, M> + ?Sized,
{
    let last = states.count() - 1;
    // Whole states first (one copy each from a slice of states), then transposed by blocks of
    // as many values as lanes, the last block padded with zeros.
    let rows: [[V::Scalar; M]; L] = core::array::from_fn(|l| states.state((k + l).min(last)));
    let mut values = [<V as crate::Real>::ZERO; M];
    for j in (0..M).step_by(L) {
        let block = core::array::from_fn(|l| {
            V::from_array(core::array::from_fn(|i| {
                rows[l]
                    .get(j + i)
                    .copied()
                    .unwrap_or(<V::Scalar as crate::Real>::ZERO)
            }))
        });
        let end = (j + L).min(M);
        values[j..end].copy_from_slice(&V::transpose(block)[..end - j]);
    }
    values
}

/// Writes the `len` results into `out`, `L` states a call of `group` (given the first state's
/// index), or one state a call of `one` for a group whose result is incomplete (a failed solve).
#[doc(hidden)]
#[inline(always)]
pub fn drive<X, O, const L: usize>(
    len: usize,
    out: &mut (impl StatesMut<O> + ?Sized),
    mut group: impl FnMut(usize) -> X,
    mut one: impl FnMut(usize) -> O,
) where
    X: SplitLanes<L, Single = O>,
{
    let mut k = 0;
    while k < len {
        let filled = (len - k).min(L);
        let x = group(k);
        if !x.is_complete() {
            for i in k..k + filled {
                out.set(i, one(i));
            }
        } else if let Some(results) = out.group::<L>(k) {
            // A whole group of results side by side: the lanes written into them in place.
            x.write_lanes(results.each_mut());
        } else {
            for l in 0..filled {
                out.set(k + l, x.lane(l));
            }
        }
        k += L;
    }
}

/// Panics unless `input` holds `len` states, in slices of one length (`ragged`: the first
/// slice of another length, and that length).
#[doc(hidden)]
#[inline(always)]
#[track_caller]
pub fn check_count(name: &str, count: usize, ragged: Option<(usize, usize)>, len: usize) {
    if let Some((j, other)) = ragged {
        panic!(
            "`{name}` has slices of different lengths: its first holds {count} states, its \
             slice {j} holds {other}"
        );
    }
    assert!(
        count == len,
        "`{name}` holds {count} states, the output {len}"
    );
}

/// Panics unless the output's slices have one length.
#[doc(hidden)]
#[inline(always)]
#[track_caller]
pub fn check_output(len: usize, ragged: Option<(usize, usize)>) {
    if let Some((j, other)) = ragged {
        panic!(
            "the output has slices of different lengths: its first holds {len} results, its \
             slice {j} holds {other}"
        );
    }
}
