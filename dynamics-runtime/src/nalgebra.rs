//! Interoperability with nalgebra's statically sized types.
//!
//! The methods of [`Dynamics`](crate::Dynamics) take and return plain arrays; for each of the
//! runtime's traits, a `...Nalgebra` trait (from the method table, `methods.rs`) wraps them for
//! `SVector` and `SMatrix`, at no cost beyond a copy: [`DynamicsNalgebra`],
//! [`DynamicsDerivativesNalgebra`], [`DynamicsRegressorNalgebra`]; the contacts' hand-written
//! traits have [`FloatingContactsNalgebra`]. A scalar result stays `T`; a
//! pose becomes an `Isometry3`, a Jacobian an `SMatrix<T, 6, N>`, the regressor one `N × 10`
//! block per link.

// The result table's types name these.
use crate::{
    ForwardDynamicsDerivatives, InverseDynamicsDerivatives, NotPositiveDefinite, Pose, Real,
};
use nalgebra::{
    Isometry3, Matrix3, RealField, Rotation3, SMatrix, SVector, Translation3, UnitQuaternion,
};

mod contacts;
pub use contacts::{
    ConstrainedDynamicsNalgebra, ContactDynamicsNalgebra, ContactTermsNalgebra,
    FloatingContactsNalgebra,
};

/// The traits from the method table's rows: for each of the runtime's traits, one of `_na`
/// wrappers, implemented for every type that implements the first.
macro_rules! declare_nalgebra {
    ($(
        $(#[doc = $_trait_doc:literal])*
        trait $trait:ident<$config:ident $(, $space:ident)* $(; $($count:ident $(= $count_default:ident)?),+)?> $(: $_supertrait:ident<$($_super_argument:ident),+>)?, nalgebra $nalgebra:ident, batch $_batch:ident {
            items { $($_items:tt)* }
            $(
                $(#[doc = $_family_doc:literal])*
                family $_family:ident { $($_family_row:tt)* }
                methods {$(
                    $(#[doc = $_doc:literal])*
                    fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $wrapper:ident $(, batch $_batch_fn:ident)? {
                        $($_row:tt)*
                    }
                )*}
            )*
        }
    )*) => {$(
        #[doc = concat!("nalgebra versions of the [`", stringify!($trait), "`](crate::", stringify!($trait), ") methods, ")]
        #[doc = concat!("implemented for every type that implements it.")]
        pub trait $nalgebra<const $config: usize $(, const $space: usize)* $($(, const $count: usize $(= $count_default)?)+)?>: crate::$trait<$config $(, $space)* $($(, $count)+)?> {
            $($(
                nalgebra_wrapper!($trait $config fn $name, $wrapper($($argument),*) -> $result);
            )*)*
        }

        impl<R: crate::$trait<$config $(, $space)* $($(, $count)+)?> + ?Sized, const $config: usize $(, const $space: usize)* $($(, const $count: usize)+)?>
            $nalgebra<$config $(, $space)* $($(, $count)+)?> for R {}
    )*};
}

/// The `_na` wrapper of one method: the arguments from nalgebra's types, the result to them.
macro_rules! nalgebra_wrapper {
    ($trait:ident $config:ident fn $name:ident, $wrapper:ident($($argument:ident),*) -> $result:ident) => {
        #[doc = concat!("[`", stringify!($trait), "::", stringify!($name), "`](crate::", stringify!($trait), "::", stringify!($name), ") with nalgebra types.")]
        fn $wrapper<T: Real + RealField>(
            &self,
            $($argument: nalgebra_argument!($argument, T, $config)),*
        ) -> nalgebra_result!($result) {
            to_nalgebra!($result, self.$name($(&array($argument)),*))
        }
    };
}

/// A method's argument as nalgebra gives it: a wrench is an `SVector<T, 6>`, the configuration
/// an `SVector<T, C>` (`C` the trait's first const parameter), the other joint variables an
/// `SVector<T, N>`.
macro_rules! nalgebra_argument {
    (q, $t:ty, $config:ident) => { &SVector<$t, $config> };
    (wrench, $t:ty, $config:ident) => { &SVector<$t, 6> };
    (wrenches, $t:ty, $config:ident) => { &[SVector<$t, 6>; TIPS] };
    ($joint:ident, $t:ty, $config:ident) => { &SVector<$t, N> };
}

for_each_method!(declare_nalgebra);

/// `into(value)`: a row's closure, typed by the value it is given.
#[inline(always)]
fn convert<A, B>(value: A, into: impl FnOnce(A) -> B) -> B {
    into(value)
}

/// An argument's nalgebra form as the array the trait takes.
trait AsArray {
    /// The array.
    type Array;
    fn as_array(&self) -> Self::Array;
}

impl<T: Real + RealField, const N: usize> AsArray for SVector<T, N> {
    type Array = [T; N];
    fn as_array(&self) -> [T; N] {
        core::array::from_fn(|i| self[i])
    }
}

/// A vector per tip (the tips' wrenches).
impl<T: Real + RealField, const M: usize, const K: usize> AsArray for [SVector<T, M>; K] {
    type Array = [[T; M]; K];
    fn as_array(&self) -> [[T; M]; K] {
        self.each_ref().map(AsArray::as_array)
    }
}

fn array<A: AsArray>(v: &A) -> A::Array {
    v.as_array()
}

fn matrix<T: Real + RealField, const N: usize>(m: &[[T; N]; N]) -> SMatrix<T, N, N> {
    SMatrix::from_fn(|i, j| m[i][j])
}

/// A pose as an isometry; the rotation matrix is taken as orthonormal.
fn isometry<T: Real + RealField>(pose: &Pose<T>) -> Isometry3<T> {
    let [x, y, z] = pose.position;
    let r = Rotation3::from_matrix_unchecked(Matrix3::from_fn(|i, j| pose.rotation[i][j]));
    Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_rotation_matrix(&r),
    )
}

#[cfg(test)]
mod tests {
    use super::{DynamicsDerivativesNalgebra, DynamicsNalgebra, DynamicsRegressorNalgebra};
    use crate::{
        Dynamics, DynamicsDerivatives, DynamicsRegressor, ForwardDynamicsDerivatives,
        InverseDynamicsDerivatives, NotPositiveDefinite, Pose, Real,
    };
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
        fn hand_pose<T: Real>(&self, q: &[T; 2]) -> Pose<T> {
            turn(sum(q))
        }
        fn link_poses<T: Real>(&self, q: &[T; 2]) -> [Pose<T>; 2] {
            [turn(sum(q)); 2]
        }
        fn hand_jacobian_in_base<T: Real>(&self, q: &[T; 2]) -> [[T; 2]; 6] {
            [[sum(q); 2]; 6]
        }
        fn hand_jacobian_in_hand<T: Real>(&self, q: &[T; 2]) -> [[T; 2]; 6] {
            [[sum(q); 2]; 6]
        }
        fn hand_acceleration_bias_in_base<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> [T; 6] {
            [sum(q); 6]
        }
        fn hand_acceleration_bias_in_hand<T: Real>(&self, q: &[T; 2], _: &[T; 2]) -> [T; 6] {
            [sum(q); 6]
        }
        fn joint_torques_for_hand_wrench<T: Real>(&self, q: &[T; 2], _: &[T; 6]) -> [T; 2] {
            [sum(q); 2]
        }
        fn joint_torques_for_base_wrench<T: Real>(&self, q: &[T; 2], _: &[T; 6]) -> [T; 2] {
            [sum(q); 2]
        }
        fn mass_matrix_inverse<T: Real>(
            &self,
            q: &[T; 2],
        ) -> Result<[[T; 2]; 2], NotPositiveDefinite> {
            Ok([[sum(q); 2]; 2])
        }
        fn forward_dynamics<T: Real>(
            &self,
            q: &[T; 2],
            _: &[T; 2],
            _: &[T; 2],
        ) -> Result<[T; 2], NotPositiveDefinite> {
            if sum(q).all_positive() {
                Ok([sum(q); 2])
            } else {
                Err(NotPositiveDefinite)
            }
        }
    }

    impl DynamicsDerivatives<2> for Sums {
        fn inverse_dynamics_derivatives<T: Real>(
            &self,
            q: &[T; 2],
            _: &[T; 2],
            _: &[T; 2],
        ) -> InverseDynamicsDerivatives<[[T; 2]; 2]> {
            InverseDynamicsDerivatives::from_blocks([[[sum(q); 2]; 2], [[-sum(q); 2]; 2]])
        }
        fn forward_dynamics_derivatives<T: Real>(
            &self,
            q: &[T; 2],
            _: &[T; 2],
            _: &[T; 2],
        ) -> Result<ForwardDynamicsDerivatives<[T; 2], [[T; 2]; 2]>, NotPositiveDefinite> {
            let m = |k: T| [[k * sum(q); 2]; 2];
            let blocks = [m(T::ONE), m(T::ONE + T::ONE), m(T::ONE + T::ONE + T::ONE)];
            Ok(ForwardDynamicsDerivatives::from_parts((
                [sum(q); 2],
                blocks,
            )))
        }
    }

    #[test]
    fn the_derivatives_have_wrappers_that_forward_them() {
        let (q, z) = (SVector::from([1.0, 2.0]), SVector::<f64, 2>::zeros());
        let m = |k: f64| SMatrix::<f64, 2, 2>::repeat(3.0 * k);
        let inverse = Sums.inverse_dynamics_derivatives_na(&q, &z, &z);
        assert_eq!((inverse.dtau_dq, inverse.dtau_dqd), (m(1.0), m(-1.0)));
        let forward = Sums
            .forward_dynamics_derivatives_na(&q, &z, &z)
            .expect("Ok");
        assert_eq!(forward.qdd, SVector::<f64, 2>::repeat(3.0));
        assert_eq!(
            (forward.dqdd_dq, forward.dqdd_dqd, forward.dqdd_dtau),
            (m(1.0), m(2.0), m(3.0))
        );
    }

    impl DynamicsRegressor<2> for Sums {
        /// Element `[i][j][k]` is `100 i + 10 j + k` plus the sum of `q`.
        fn regressor<T: Real>(&self, q: &[T; 2], _: &[T; 2], _: &[T; 2]) -> [[[T; 10]; 2]; 2] {
            core::array::from_fn(|i| {
                core::array::from_fn(|j| {
                    core::array::from_fn(|k| T::from_f64((100 * i + 10 * j + k) as f64) + sum(q))
                })
            })
        }
        fn joint_regressor<T: Real>(&self, qd: &[T; 2], _: &[T; 2]) -> [[T; 4]; 2] {
            core::array::from_fn(|i| {
                core::array::from_fn(|k| T::from_f64((10 * i + k) as f64) + sum(qd))
            })
        }
        fn joint_parameters<T: Real>(&self) -> [[T; 4]; 2] {
            [[T::ONE; 4]; 2]
        }
        fn standard_parameters<T: Real>(&self) -> [[T; 10]; 2] {
            core::array::from_fn(|j| core::array::from_fn(|k| T::from_f64((10 * j + k) as f64)))
        }
    }

    #[test]
    fn the_regressor_has_wrappers_with_a_block_per_link() {
        let (q, z) = (SVector::from([1.0, 2.0]), SVector::<f64, 2>::zeros());
        let blocks = Sums.regressor_na(&q, &z, &z);
        for (j, block) in blocks.iter().enumerate() {
            let expected =
                SMatrix::<f64, 2, 10>::from_fn(|i, k| (100 * i + 10 * j + k) as f64 + 3.0);
            assert_eq!(*block, expected);
        }
        let joints = Sums.joint_regressor_na(&q, &z);
        assert_eq!(
            joints,
            SMatrix::<f64, 2, 4>::from_fn(|i, k| (10 * i + k) as f64 + 3.0)
        );
        assert_eq!(
            Sums.joint_parameters_na::<f64>(),
            SMatrix::<f64, 2, 4>::repeat(1.0)
        );
        let parameters = Sums.standard_parameters_na::<f64>();
        assert_eq!(
            parameters[1],
            SVector::<f64, 10>::from_fn(|k, _| (10 + k) as f64)
        );
    }

    /// A quarter turn about z, placed at `(x, 0, 0)`.
    fn turn<T: Real>(x: T) -> Pose<T> {
        let (o, l) = (T::ZERO, T::ONE);
        Pose {
            rotation: [[o, -l, o], [l, o, o], [o, o, l]],
            position: [x, o, o],
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
        let w = SVector::<f64, 6>::zeros();
        let (j, s) = (
            SMatrix::<f64, 6, 2>::repeat(3.0),
            SVector::<f64, 6>::repeat(3.0),
        );
        assert_eq!(Sums.hand_jacobian_in_base_na(&q), j);
        assert_eq!(Sums.hand_jacobian_in_hand_na(&q), j);
        assert_eq!(Sums.hand_acceleration_bias_in_base_na(&q, &z), s);
        assert_eq!(Sums.hand_acceleration_bias_in_hand_na(&q, &z), s);
        assert_eq!(Sums.joint_torques_for_hand_wrench_na(&q, &w), v);
        assert_eq!(Sums.joint_torques_for_base_wrench_na(&q, &w), v);
        assert_eq!(Sums.mass_matrix_inverse_na(&q), Ok(m));
        assert_eq!(Sums.forward_dynamics_na(&q, &z, &z), Ok(v));
        assert_eq!(
            Sums.forward_dynamics_na(&-q, &z, &z),
            Err(NotPositiveDefinite)
        );
        let point = nalgebra::Point3::new(1.0, 0.0, 0.0);
        let moved = nalgebra::Point3::new(3.0, 1.0, 0.0);
        assert!((Sums.hand_pose_na(&q) * point - moved).norm() < 1e-15);
        for pose in Sums.link_poses_na(&q) {
            assert!((pose * point - moved).norm() < 1e-15);
        }
    }
}
