//! The entries of the robots on a free-flying base ([`floating`]): `tau`, `M`, `h` and `g` of
//! `FloatingDynamics<Q, V>`, each reading `Q` values from `q` and `V` from the other inputs and
//! writing `V` values (`V × V` for `M`, row-major); `dynamics_bench_dof` gives `V`.

use super::{input, output, output_matrix, Function, Robot};
use dynamics_runtime::FloatingDynamics;

/// The timed functions of one robot type on a free-flying base, as C functions.
struct Floating<R, const Q: usize, const V: usize>(core::marker::PhantomData<R>);

impl<R: FloatingDynamics<Q, V> + Default, const Q: usize, const V: usize> Floating<R, Q, V> {
    unsafe extern "C" fn tau(q: *const f64, v: *const f64, a: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, with `Q` values at `q`.
        unsafe {
            output(
                out,
                R::default().inverse_dynamics(input(q), input(v), input(a)),
            )
        }
    }

    unsafe extern "C" fn mass(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (room for V × V values at `out`).
        unsafe { output_matrix(out, R::default().mass_matrix(input::<Q>(q))) }
    }

    unsafe extern "C" fn bias(q: *const f64, v: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().bias_forces(input(q), input(v))) }
    }

    unsafe extern "C" fn gravity(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().generalized_gravity(input::<Q>(q))) }
    }

    fn get(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"tau" => Self::tau,
            b"M" => Self::mass,
            b"h" => Self::bias,
            b"g" => Self::gravity,
            _ => return None,
        })
    }
}

/// The entry of the robot `R` on a free-flying base: `V` generalized velocities, no base
/// parameters.
pub(super) fn floating<R: FloatingDynamics<Q, V> + Default, const Q: usize, const V: usize>(
    _: &R,
) -> Robot {
    (V, 0, Floating::<R, Q, V>::get)
}

#[cfg(test)]
mod tests {
    use crate::{dynamics_bench_dof, dynamics_bench_function, Function};
    use dynamics_bench::{floating_samples, scaled_error, AnymalB, Solo12, G1};
    use dynamics_runtime::FloatingDynamics;

    fn lookup(robot: &str, function: &str) -> Option<Function> {
        let robot = std::ffi::CString::new(robot).unwrap();
        let function = std::ffi::CString::new(function).unwrap();
        // SAFETY: two NUL-terminated strings.
        unsafe { dynamics_bench_function(robot.as_ptr(), function.as_ptr()) }
    }

    /// The robot's functions through the C ABI: each the trait method's bits, nothing written
    /// past its output, and Pinocchio's numbers (the data) to 1e-9 as `bench.cpp` checks them.
    fn check_floating<R, const Q: usize, const V: usize>(r: &R, robot: &str)
    where
        R: FloatingDynamics<Q, V>,
    {
        let name = std::ffi::CString::new(robot).unwrap();
        // SAFETY: a NUL-terminated string.
        assert_eq!(unsafe { dynamics_bench_dof(name.as_ptr()) }, V, "{robot}");
        for s in floating_samples::<Q, V>(robot) {
            let mass: Vec<f64> = r.mass_matrix(&s.q).iter().flatten().copied().collect();
            let checks = [
                (
                    "tau",
                    r.inverse_dynamics(&s.q, &s.v, &s.a).to_vec(),
                    s.tau.to_vec(),
                ),
                ("M", mass, s.mass.clone()),
                ("h", r.bias_forces(&s.q, &s.v).to_vec(), s.bias.to_vec()),
                (
                    "g",
                    r.generalized_gravity(&s.q).to_vec(),
                    s.gravity.to_vec(),
                ),
            ];
            for (function, want, pinocchio) in checks {
                let f = lookup(robot, function).expect("a floating robot's function");
                let mut got = vec![f64::NAN; V * V + 1];
                // SAFETY: Q values at q, V at v and a, room for V × V outputs and one more.
                unsafe { f(s.q.as_ptr(), s.v.as_ptr(), s.a.as_ptr(), got.as_mut_ptr()) };
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                assert_eq!(bits(&got[..want.len()]), bits(&want), "{robot} {function}");
                assert!(
                    got[want.len()..].iter().all(|x| x.is_nan()),
                    "{robot} {function}"
                );
                let error = scaled_error(&want, &pinocchio);
                assert!(error < 1e-9, "{robot} {function}: {error:e} from Pinocchio");
            }
        }
        for function in [
            "C",
            "fk",
            "J",
            "fd",
            "Minv",
            "dtau",
            "dqdd",
            "Y",
            "tau_batch",
        ] {
            assert!(lookup(robot, function).is_none(), "{robot} {function}");
        }
    }

    #[test]
    fn the_floating_robots_through_the_c_abi_equal_the_trait_methods_and_pinocchio() {
        check_floating(&Solo12, "solo12");
        check_floating(&AnymalB, "anymal_b");
        check_floating(&G1, "g1_29dof");
    }
}
