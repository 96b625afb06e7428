//! Interoperability with nalgebra's statically sized types.
//!
//! The [`Dynamics`] methods take and return plain arrays; [`DynamicsNalgebra`] wraps them
//! for `SVector` and `SMatrix`, at no cost beyond a copy.

use crate::{Dynamics, Real};
use nalgebra::{SMatrix, SVector, Scalar};

/// nalgebra versions of the [`Dynamics`] methods, implemented for every robot.
pub trait DynamicsNalgebra<const N: usize>: Dynamics<N> {
    /// [`Dynamics::mass_matrix`] with nalgebra types.
    fn mass_matrix_na<T: Real + Scalar>(&self, q: &SVector<T, N>) -> SMatrix<T, N, N> {
        matrix(&self.mass_matrix(&array(q)))
    }
    /// [`Dynamics::coriolis_matrix`] with nalgebra types.
    fn coriolis_matrix_na<T: Real + Scalar>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> SMatrix<T, N, N> {
        matrix(&self.coriolis_matrix(&array(q), &array(qd)))
    }
    /// [`Dynamics::gravity_torques`] with nalgebra types.
    fn gravity_torques_na<T: Real + Scalar>(&self, q: &SVector<T, N>) -> SVector<T, N> {
        SVector::from(self.gravity_torques(&array(q)))
    }
    /// [`Dynamics::bias_torques`] with nalgebra types.
    fn bias_torques_na<T: Real + Scalar>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> SVector<T, N> {
        SVector::from(self.bias_torques(&array(q), &array(qd)))
    }
    /// [`Dynamics::inverse_dynamics`] with nalgebra types.
    fn inverse_dynamics_na<T: Real + Scalar>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N> {
        SVector::from(self.inverse_dynamics(&array(q), &array(qd), &array(qdd)))
    }
}

impl<R: Dynamics<N> + ?Sized, const N: usize> DynamicsNalgebra<N> for R {}

fn array<T: Real + Scalar, const N: usize>(v: &SVector<T, N>) -> [T; N] {
    core::array::from_fn(|i| v[i])
}

fn matrix<T: Real + Scalar, const N: usize>(m: &[[T; N]; N]) -> SMatrix<T, N, N> {
    SMatrix::from_fn(|i, j| m[i][j])
}
