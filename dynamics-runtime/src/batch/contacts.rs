//! The contacts' methods over many states ([`FloatingContactsBatch`]): written by hand, as
//! the traits are, on the module's layouts and lanes. A frame's input is `[T; 6]` (a wrench) or
//! `[T; 3]` (a force) per frame and state: a slice of states `&[[[T; 6]; F]]`, or one slice per
//! frame `[&[[T; 6]]; F]`. The contacts held are an input per state too (`&[[bool; F]]`,
//! `&[[Contact; F]]`): a group of states that hold the same contacts is evaluated in lanes, a
//! group whose contacts differ state by state (and one whose solve fails in a lane) one state
//! at a time, each state's result the bits of its own call.

use super::{check_count, check_output, drive, lanes, BatchScalar, States, StatesMut};
use crate::lanes::{gather, Lanes, SplitLanes};
use crate::{
    ConstrainedDynamics, Contact, ContactDynamics, ContactError, ContactTerms,
    FloatingContactTerms, FloatingContacts, NotPositiveDefinite,
};

/// The frames' `M` values of states `k` to `k + L − 1` as lanes, the last state repeated past
/// the end.
#[inline(always)]
fn frame_lanes<X, S, const L: usize, const M: usize, const F: usize>(
    states: &S,
    k: usize,
) -> [[X; M]; F]
where
    X: Lanes<L>,
    S: States<[X::Scalar; M], F> + ?Sized,
{
    let last = states.count() - 1;
    let rows: [[[X::Scalar; M]; F]; L] = core::array::from_fn(|l| states.state((k + l).min(last)));
    core::array::from_fn(|f| gather(&core::array::from_fn(|l| rows[l][f])))
}

/// The contacts of group `k`'s states if all are the same (the last state repeated past the
/// end), else `None`.
#[inline(always)]
fn shared<C, S, const L: usize, const F: usize>(contacts: &S, k: usize) -> Option<[C; F]>
where
    C: Copy + PartialEq,
    S: States<C, F> + ?Sized,
{
    let last = contacts.count() - 1;
    let first = contacts.state(k);
    (1..L)
        .all(|l| contacts.state((k + l).min(last)) == first)
        .then_some(first)
}

/// The output's length, after checking it and each input (`check_count`'s panics, naming the
/// argument).
macro_rules! checked {
    ($out:ident; $($input:ident),+) => {{
        let len = $out.count();
        check_output(len, $out.ragged());
        $(check_count(stringify!($input), $input.count(), $input.ragged(), len);)+
        len
    }};
}

impl<X: SplitLanes<L>, const L: usize, const V: usize, const F: usize> SplitLanes<L>
    for ContactDynamics<X, V, F>
{
    type Single = ContactDynamics<X::Single, V, F>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        ContactDynamics {
            acceleration: self.acceleration.lane(l),
            forces: self.forces.lane(l),
        }
    }
}

impl<X: SplitLanes<L>, const L: usize, const V: usize, const F: usize> SplitLanes<L>
    for ConstrainedDynamics<X, V, F>
{
    type Single = ConstrainedDynamics<X::Single, V, F>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        ConstrainedDynamics {
            acceleration: self.acceleration.lane(l),
            wrenches: self.wrenches.lane(l),
        }
    }
}

impl<X: SplitLanes<L>, const L: usize, const V: usize, const F: usize> SplitLanes<L>
    for ContactTerms<X, V, F>
{
    type Single = ContactTerms<X::Single, V, F>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        ContactTerms {
            free_acceleration: self.free_acceleration.lane(l),
            frame_accelerations: self.frame_accelerations.lane(l),
            minv_jt: self.minv_jt.lane(l),
            delassus: self.delassus.lane(l),
        }
    }
}

/// The [`FloatingContacts`] methods and [`FloatingContactTerms::contact_terms`] over many
/// states ([`batch`](crate::batch)), implemented for every type that implements the first.
///
/// # Panics
///
/// Each method: if an input does not hold as many states as `out`, or the slices of one (one
/// per coordinate or frame) or of `out` differ in length.
pub trait FloatingContactsBatch<const Q: usize, const V: usize, const F: usize>:
    FloatingContacts<Q, V, F>
{
    /// [`FloatingContacts::inverse_dynamics_with_wrenches`] of every state, into `out`.
    #[inline]
    #[track_caller]
    fn inverse_dynamics_with_wrenches_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        a: &(impl States<T, V> + ?Sized),
        wrenches: &(impl States<[T; 6], F> + ?Sized),
        out: &mut (impl StatesMut<[T; V]> + ?Sized),
    ) {
        let len = checked!(out; q, v, a, wrenches);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                self.inverse_dynamics_with_wrenches::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(a, k),
                    &frame_lanes::<T::Lanes, _, L, 6, F>(wrenches, k),
                )
            },
            |k| {
                let w = wrenches.state(k);
                self.inverse_dynamics_with_wrenches(&q.state(k), &v.state(k), &a.state(k), &w)
            },
        );
    }

    /// [`FloatingContacts::inverse_dynamics_with_forces`] of every state, into `out`.
    #[inline]
    #[track_caller]
    fn inverse_dynamics_with_forces_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        a: &(impl States<T, V> + ?Sized),
        forces: &(impl States<[T; 3], F> + ?Sized),
        out: &mut (impl StatesMut<[T; V]> + ?Sized),
    ) {
        let len = checked!(out; q, v, a, forces);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                self.inverse_dynamics_with_forces::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(a, k),
                    &frame_lanes::<T::Lanes, _, L, 3, F>(forces, k),
                )
            },
            |k| {
                let f = forces.state(k);
                self.inverse_dynamics_with_forces(&q.state(k), &v.state(k), &a.state(k), &f)
            },
        );
    }

    /// [`FloatingContacts::forward_dynamics_with_wrenches`] of every state, into `out`.
    #[inline]
    #[track_caller]
    fn forward_dynamics_with_wrenches_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        tau: &(impl States<T, V> + ?Sized),
        wrenches: &(impl States<[T; 6], F> + ?Sized),
        out: &mut (impl StatesMut<Result<[T; V], NotPositiveDefinite>> + ?Sized),
    ) {
        let len = checked!(out; q, v, tau, wrenches);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                self.forward_dynamics_with_wrenches::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(tau, k),
                    &frame_lanes::<T::Lanes, _, L, 6, F>(wrenches, k),
                )
            },
            |k| {
                let w = wrenches.state(k);
                self.forward_dynamics_with_wrenches(&q.state(k), &v.state(k), &tau.state(k), &w)
            },
        );
    }

    /// [`FloatingContacts::forward_dynamics_with_forces`] of every state, into `out`.
    #[inline]
    #[track_caller]
    fn forward_dynamics_with_forces_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        tau: &(impl States<T, V> + ?Sized),
        forces: &(impl States<[T; 3], F> + ?Sized),
        out: &mut (impl StatesMut<Result<[T; V], NotPositiveDefinite>> + ?Sized),
    ) {
        let len = checked!(out; q, v, tau, forces);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                self.forward_dynamics_with_forces::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(tau, k),
                    &frame_lanes::<T::Lanes, _, L, 3, F>(forces, k),
                )
            },
            |k| {
                let f = forces.state(k);
                self.forward_dynamics_with_forces(&q.state(k), &v.state(k), &tau.state(k), &f)
            },
        );
    }

    /// [`FloatingContactTerms::contact_terms`] of every state, into `out`.
    #[inline]
    #[track_caller]
    fn contact_terms_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        tau: &(impl States<T, V> + ?Sized),
        out: &mut (impl StatesMut<Result<ContactTerms<T, V, F>, NotPositiveDefinite>> + ?Sized),
    ) {
        let len = checked!(out; q, v, tau);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                <Self as FloatingContactTerms<Q, V, F>>::contact_terms::<T::Lanes>(
                    self,
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(tau, k),
                )
            },
            |k| {
                <Self as FloatingContactTerms<Q, V, F>>::contact_terms(
                    self,
                    &q.state(k),
                    &v.state(k),
                    &tau.state(k),
                )
            },
        );
    }

    /// [`FloatingContacts::contact_dynamics`] of every state, into `out`, state k with the
    /// frames `in_contact`'s state k holds.
    #[inline]
    #[track_caller]
    fn contact_dynamics_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        tau: &(impl States<T, V> + ?Sized),
        in_contact: &(impl States<bool, F> + ?Sized),
        out: &mut (impl StatesMut<Result<ContactDynamics<T, V, F>, ContactError>> + ?Sized),
    ) {
        let len = checked!(out; q, v, tau, in_contact);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                // Not the same frames in every lane: the group state by state (`Err` here).
                let held =
                    shared::<_, _, L, F>(in_contact, k).ok_or(ContactError::DependentContacts)?;
                self.contact_dynamics::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(tau, k),
                    &held,
                )
            },
            |k| {
                let held = in_contact.state(k);
                self.contact_dynamics(&q.state(k), &v.state(k), &tau.state(k), &held)
            },
        );
    }

    /// [`FloatingContacts::constrained_dynamics`] of every state, into `out`, state k with the
    /// frames held as `contacts`' state k says.
    #[inline]
    #[track_caller]
    fn constrained_dynamics_batch<T: BatchScalar<L>, const L: usize>(
        &self,
        q: &(impl States<T, Q> + ?Sized),
        v: &(impl States<T, V> + ?Sized),
        tau: &(impl States<T, V> + ?Sized),
        contacts: &(impl States<Contact, F> + ?Sized),
        out: &mut (impl StatesMut<Result<ConstrainedDynamics<T, V, F>, ContactError>> + ?Sized),
    ) {
        let len = checked!(out; q, v, tau, contacts);
        drive::<_, _, L>(
            len,
            out,
            |k| {
                let held =
                    shared::<_, _, L, F>(contacts, k).ok_or(ContactError::DependentContacts)?;
                self.constrained_dynamics::<T::Lanes>(
                    &lanes::<T::Lanes, _, L, _>(q, k),
                    &lanes::<T::Lanes, _, L, _>(v, k),
                    &lanes::<T::Lanes, _, L, _>(tau, k),
                    &held,
                )
            },
            |k| {
                let held = contacts.state(k);
                self.constrained_dynamics(&q.state(k), &v.state(k), &tau.state(k), &held)
            },
        );
    }
}

impl<R, const Q: usize, const V: usize, const F: usize> FloatingContactsBatch<Q, V, F> for R where
    R: FloatingContacts<Q, V, F> + ?Sized
{
}
