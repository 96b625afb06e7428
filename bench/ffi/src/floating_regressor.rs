//! `Y` of a robot on a free-flying base derived with `regressor = true` (Solo 12):
//! `FloatingDynamicsRegressor::regressor_into`, `V × 10 L` row-major, `L = n + 1` bodies, the
//! floating one first (Pinocchio's `computeJointTorqueRegressor` layout on a free flyer), beside
//! the functions of [`super::floating`].

use super::floating::Contacts;
use super::{input, Function, Robot};
use dynamics_runtime::{FloatingContacts, FloatingDynamicsDerivatives, FloatingDynamicsRegressor};

/// The regressor of a robot derived with `regressor = true` (`Y`), beside its other functions.
struct Regressor<R, const Q: usize, const V: usize, const F: usize, const L: usize>(
    core::marker::PhantomData<R>,
);

impl<R, const Q: usize, const V: usize, const F: usize, const L: usize> Regressor<R, Q, V, F, L>
where
    R: FloatingDynamicsDerivatives<Q, V>
        + FloatingContacts<Q, V, F>
        + FloatingDynamicsRegressor<Q, V, L>
        + Default,
{
    unsafe extern "C" fn regressor(q: *const f64, v: *const f64, a: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (room for V × 10 L values at `out`, which holds
        // `f64`s, so it is aligned for them). Written in place, as Pinocchio writes its
        // `data.jointTorqueRegressor`.
        unsafe {
            let y = &mut *out.cast::<[[[f64; 10]; L]; V]>();
            R::default().regressor_into(input::<Q>(q), input(v), input(a), y);
        }
    }

    fn get(function: &[u8]) -> Option<Function> {
        match function {
            b"Y" => Some(Self::regressor),
            _ => Contacts::<R, Q, V, F>::get(function),
        }
    }
}

/// The entry of a robot on a free-flying base with its regressor (`Y`): `V` generalized
/// velocities, no base parameters.
pub(super) fn floating_with_regressor<
    R,
    const Q: usize,
    const V: usize,
    const F: usize,
    const L: usize,
>(
    _: &R,
) -> Robot
where
    R: FloatingDynamicsDerivatives<Q, V>
        + FloatingContacts<Q, V, F>
        + FloatingDynamicsRegressor<Q, V, L>
        + Default,
{
    (V, 0, Regressor::<R, Q, V, F, L>::get)
}

#[cfg(test)]
mod tests {
    use crate::floating::tests::{lookup, with_room};
    use dynamics_bench::{floating_regressor_samples, floating_samples, scaled_error, Solo12};
    use dynamics_runtime::FloatingDynamicsRegressor;

    /// `Y` through the C ABI (Solo 12): `regressor`'s bits, nothing written past its output,
    /// and Pinocchio's `computeJointTorqueRegressor` (`solo12_regressor.json`) to 1e-9.
    #[test]
    fn the_floating_regressor_through_the_c_abi_equals_the_trait_method_and_pinocchio() {
        with_room(|| {
            const C: usize = 10 * 13;
            let f = lookup("solo12", "Y").expect("Solo 12's regressor");
            let states = floating_samples::<19, 18>("solo12");
            let pinocchio = floating_regressor_samples::<18, C>("solo12");
            assert_eq!(states.len(), pinocchio.len());
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
            for (s, expected) in states.iter().zip(&pinocchio) {
                let want: Vec<f64> = Solo12
                    .regressor(&s.q, &s.v, &s.a)
                    .iter()
                    .flatten()
                    .flatten()
                    .copied()
                    .collect();
                let mut got = vec![f64::NAN; 18 * C + 1];
                // SAFETY: 19 values at q, 18 at v and a, room for 18 × 130 and one more.
                unsafe { f(s.q.as_ptr(), s.v.as_ptr(), s.a.as_ptr(), got.as_mut_ptr()) };
                assert_eq!(bits(&got[..18 * C]), bits(&want), "solo12 Y");
                assert!(got[18 * C].is_nan(), "solo12 Y");
                let error = scaled_error(&want, expected);
                assert!(error < 1e-9, "solo12 Y: {error:e} from Pinocchio");
            }
        });
    }
}
