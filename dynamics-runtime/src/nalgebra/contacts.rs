//! The contacts' methods ([`FloatingContacts`], [`FloatingContactTerms`],
//! [`ContactTerms::solve`]) with nalgebra's types: written by hand, as the traits are (their
//! results are none of the method table's), each a copy around the array method.
//!
//! A frame's vector is an `SVector<T, 6>` (a wrench `[f, m]`) or a `Vector3<T>` (a force), one
//! per frame in an array `[_; F]`, as the tips' wrenches of the table's `_na` methods are.

use crate::{
    ConstrainedDynamics, Contact, ContactDynamics, ContactError, ContactTerms,
    FloatingContactTerms, FloatingContacts, NotPositiveDefinite, Real,
};
use nalgebra::{Matrix3, RealField, SMatrix, SVector, Vector3};

/// [`ContactDynamics`] with nalgebra's types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactDynamicsNalgebra<T: RealField, const V: usize, const F: usize> {
    /// `a`.
    pub acceleration: SVector<T, V>,
    /// `λ_f` per frame, in world axes; zero for a frame not in contact.
    pub forces: [Vector3<T>; F],
}

/// [`ConstrainedDynamics`] with nalgebra's types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstrainedDynamicsNalgebra<T: RealField, const V: usize, const F: usize> {
    /// `a`.
    pub acceleration: SVector<T, V>,
    /// The wrench `[f, m]` per frame, in world axes, about the frame's origin.
    pub wrenches: [SVector<T, 6>; F],
}

/// [`ContactTerms`] with nalgebra's types: `M⁻¹ J_fᵀ` a `V × 3` block per frame, `Λ⁻¹` a 3 × 3
/// block per pair of frames.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactTermsNalgebra<T: RealField, const V: usize, const F: usize> {
    /// `a₀`.
    pub free_acceleration: SVector<T, V>,
    /// `J_f a₀ + γ_f` per frame.
    pub frame_accelerations: [Vector3<T>; F],
    /// `M⁻¹ J_fᵀ` per frame, its column i for world axis i.
    pub minv_jt: [SMatrix<T, V, 3>; F],
    /// `Λ⁻¹`'s block `[f][g]`: frame f's acceleration per unit force at frame g.
    pub delassus: [[Matrix3<T>; F]; F],
}

impl<T: Real + RealField, const V: usize, const F: usize> From<ContactTerms<T, V, F>>
    for ContactTermsNalgebra<T, V, F>
{
    fn from(t: ContactTerms<T, V, F>) -> Self {
        Self {
            free_acceleration: SVector::from(t.free_acceleration),
            frame_accelerations: t.frame_accelerations.map(Vector3::from),
            minv_jt: t.minv_jt.map(|c| SMatrix::from_fn(|k, i| c[i][k])),
            delassus: core::array::from_fn(|f| {
                core::array::from_fn(|g| Matrix3::from_fn(|i, j| t.delassus[f][i][g][j]))
            }),
        }
    }
}

impl<T: Real + RealField, const V: usize, const F: usize> From<&ContactTermsNalgebra<T, V, F>>
    for ContactTerms<T, V, F>
{
    fn from(t: &ContactTermsNalgebra<T, V, F>) -> Self {
        Self {
            free_acceleration: array(&t.free_acceleration),
            frame_accelerations: t.frame_accelerations.each_ref().map(array),
            minv_jt: t
                .minv_jt
                .each_ref()
                .map(|c| core::array::from_fn(|i| core::array::from_fn(|k| c[(k, i)]))),
            delassus: core::array::from_fn(|f| {
                core::array::from_fn(|i| {
                    core::array::from_fn(|g| core::array::from_fn(|j| t.delassus[f][g][(i, j)]))
                })
            }),
        }
    }
}

impl<T: Real + RealField, const V: usize, const F: usize> ContactTermsNalgebra<T, V, F> {
    /// [`ContactTerms::solve`].
    ///
    /// # Errors
    ///
    /// As [`ContactTerms::solve`].
    pub fn solve(
        &self,
        in_contact: &[bool; F],
    ) -> Result<ContactDynamicsNalgebra<T, V, F>, ContactError> {
        ContactTerms::from(self).solve(in_contact).map(contact)
    }
}

fn array<T: Real + RealField, const N: usize>(x: &SVector<T, N>) -> [T; N] {
    core::array::from_fn(|i| x[i])
}

fn contact<T: Real + RealField, const V: usize, const F: usize>(
    d: ContactDynamics<T, V, F>,
) -> ContactDynamicsNalgebra<T, V, F> {
    ContactDynamicsNalgebra {
        acceleration: SVector::from(d.acceleration),
        forces: d.forces.map(Vector3::from),
    }
}

/// nalgebra versions of the [`FloatingContacts`] methods and of
/// [`FloatingContactTerms::contact_terms`], implemented for every type that implements the
/// first.
pub trait FloatingContactsNalgebra<const Q: usize, const V: usize, const F: usize>:
    FloatingContacts<Q, V, F>
{
    /// [`FloatingContacts::inverse_dynamics_with_wrenches`] with nalgebra types.
    fn inverse_dynamics_with_wrenches_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        a: &SVector<T, V>,
        wrenches: &[SVector<T, 6>; F],
    ) -> SVector<T, V> {
        let w = wrenches.each_ref().map(array);
        SVector::from(self.inverse_dynamics_with_wrenches(&array(q), &array(v), &array(a), &w))
    }

    /// [`FloatingContacts::inverse_dynamics_with_forces`] with nalgebra types.
    fn inverse_dynamics_with_forces_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        a: &SVector<T, V>,
        forces: &[Vector3<T>; F],
    ) -> SVector<T, V> {
        let f = forces.each_ref().map(array);
        SVector::from(self.inverse_dynamics_with_forces(&array(q), &array(v), &array(a), &f))
    }

    /// [`FloatingContacts::forward_dynamics_with_wrenches`] with nalgebra types.
    ///
    /// # Errors
    ///
    /// As the array method.
    fn forward_dynamics_with_wrenches_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        tau: &SVector<T, V>,
        wrenches: &[SVector<T, 6>; F],
    ) -> Result<SVector<T, V>, NotPositiveDefinite> {
        let w = wrenches.each_ref().map(array);
        self.forward_dynamics_with_wrenches(&array(q), &array(v), &array(tau), &w)
            .map(SVector::from)
    }

    /// [`FloatingContacts::forward_dynamics_with_forces`] with nalgebra types.
    ///
    /// # Errors
    ///
    /// As the array method.
    fn forward_dynamics_with_forces_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        tau: &SVector<T, V>,
        forces: &[Vector3<T>; F],
    ) -> Result<SVector<T, V>, NotPositiveDefinite> {
        let f = forces.each_ref().map(array);
        self.forward_dynamics_with_forces(&array(q), &array(v), &array(tau), &f)
            .map(SVector::from)
    }

    /// [`FloatingContacts::contact_dynamics`] with nalgebra types.
    ///
    /// # Errors
    ///
    /// As the array method.
    fn contact_dynamics_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        tau: &SVector<T, V>,
        in_contact: &[bool; F],
    ) -> Result<ContactDynamicsNalgebra<T, V, F>, ContactError> {
        self.contact_dynamics(&array(q), &array(v), &array(tau), in_contact)
            .map(contact)
    }

    /// [`FloatingContacts::constrained_dynamics`] with nalgebra types.
    ///
    /// # Errors
    ///
    /// As the array method.
    fn constrained_dynamics_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        tau: &SVector<T, V>,
        contacts: &[Contact; F],
    ) -> Result<ConstrainedDynamicsNalgebra<T, V, F>, ContactError> {
        let d: ConstrainedDynamics<T, V, F> =
            self.constrained_dynamics(&array(q), &array(v), &array(tau), contacts)?;
        Ok(ConstrainedDynamicsNalgebra {
            acceleration: SVector::from(d.acceleration),
            wrenches: d.wrenches.map(SVector::from),
        })
    }

    /// [`FloatingContactTerms::contact_terms`] with nalgebra types.
    ///
    /// # Errors
    ///
    /// As the array method.
    fn contact_terms_na<T: Real + RealField>(
        &self,
        q: &SVector<T, Q>,
        v: &SVector<T, V>,
        tau: &SVector<T, V>,
    ) -> Result<ContactTermsNalgebra<T, V, F>, NotPositiveDefinite> {
        <Self as FloatingContactTerms<Q, V, F>>::contact_terms(
            self,
            &array(q),
            &array(v),
            &array(tau),
        )
        .map(ContactTermsNalgebra::from)
    }
}

impl<R, const Q: usize, const V: usize, const F: usize> FloatingContactsNalgebra<Q, V, F> for R where
    R: FloatingContacts<Q, V, F> + ?Sized
{
}
