//! Interoperability with nalgebra's statically sized types.
//!
//! The [`Dynamics`] methods take and return plain arrays; [`DynamicsNalgebra`] wraps each of
//! them (from the method table, `methods.rs`) for `SVector` and `SMatrix`, at no cost beyond a
//! copy. A scalar result stays `T`.

use crate::{Dynamics, Real};
use nalgebra::{SMatrix, SVector, Scalar};

/// The trait from the method table's rows: one `_na` wrapper per method.
macro_rules! declare_nalgebra {
    ($(
        $(#[$_doc:meta])*
        fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $wrapper:ident { $($_info:tt)* }
    )*) => {
        /// nalgebra versions of the [`Dynamics`] methods, implemented for every robot.
        pub trait DynamicsNalgebra<const N: usize>: Dynamics<N> {
            $(
                #[doc = concat!("[`Dynamics::", stringify!($name), "`] with nalgebra types.")]
                fn $wrapper<T: Real + Scalar>(
                    &self,
                    $($argument: &SVector<T, N>),*
                ) -> nalgebra_result!($result, T, N) {
                    nalgebra_result!($result, self.$name($(&array($argument)),*))
                }
            )*
        }
    };
}

/// A method's result as nalgebra returns it: its type (`$result, T, N`), or the conversion of
/// an array result (`$result, value`).
macro_rules! nalgebra_result {
    (matrix, $t:ty, $n:ident) => { SMatrix<$t, $n, $n> };
    (vector, $t:ty, $n:ident) => { SVector<$t, $n> };
    (scalar, $t:ty, $n:ident) => { $t };
    (matrix, $value:expr) => { matrix(&$value) };
    (vector, $value:expr) => { SVector::from($value) };
    (scalar, $value:expr) => { $value };
}

for_each_method!(declare_nalgebra);

impl<R: Dynamics<N> + ?Sized, const N: usize> DynamicsNalgebra<N> for R {}

fn array<T: Real + Scalar, const N: usize>(v: &SVector<T, N>) -> [T; N] {
    core::array::from_fn(|i| v[i])
}

fn matrix<T: Real + Scalar, const N: usize>(m: &[[T; N]; N]) -> SMatrix<T, N, N> {
    SMatrix::from_fn(|i, j| m[i][j])
}

#[cfg(test)]
mod tests {
    use super::DynamicsNalgebra;
    use crate::{Dynamics, Real};
    use nalgebra::{SMatrix, SVector};

    /// A "robot" whose every method returns its first argument's sum, in every element.
    struct Sums;

    fn sum<T: Real>(v: &[T; 2]) -> T {
        v[0] + v[1]
    }

    impl Dynamics<2> for Sums {
        fn mass_matrix<T: Real>(&self, q: &[T; 2]) -> [[T; 2]; 2] {
            [[sum(q); 2]; 2]
        }
        fn coriolis_matrix<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> [[T; 2]; 2] {
            [[sum(q); 2]; 2]
        }
        fn coriolis_torques<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> [T; 2] {
            [sum(q); 2]
        }
        fn gravity_torques<T: Real>(&self, q: &[T; 2]) -> [T; 2] {
            [sum(q); 2]
        }
        fn bias_torques<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> [T; 2] {
            [sum(q); 2]
        }
        fn inverse_dynamics<T: Real>(&self, q: &[T; 2], _: &[T; 2], _: &[T; 2]) -> [T; 2] {
            [sum(q); 2]
        }
        fn kinetic_energy<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> T {
            sum(q)
        }
        fn potential_energy<T: Real>(&self, q: &[T; 2]) -> T {
            sum(q)
        }
    }

    #[test]
    fn every_method_has_a_wrapper_that_forwards_it() {
        let (q, z) = (SVector::from([1.0, 2.0]), SVector::<f64, 2>::zeros());
        let (m, v) = (
            SMatrix::<f64, 2, 2>::repeat(3.0),
            SVector::<f64, 2>::repeat(3.0),
        );
        assert_eq!(Sums.mass_matrix_na(&q), m);
        assert_eq!(Sums.coriolis_matrix_na(&q, &z), m);
        assert_eq!(Sums.coriolis_torques_na(&q, &z), v);
        assert_eq!(Sums.gravity_torques_na(&q), v);
        assert_eq!(Sums.bias_torques_na(&q, &z), v);
        assert_eq!(Sums.inverse_dynamics_na(&q, &z, &z), v);
        assert_eq!(Sums.kinetic_energy_na(&q, &z), 3.0);
        assert_eq!(Sums.potential_energy_na(&q), 3.0);
    }
}
