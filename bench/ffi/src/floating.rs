//! The entries of the robots on a free-flying base ([`floating`]): `tau`, `M`, `h` and `g` of
//! `FloatingDynamics<Q, V>`, each reading `Q` values from `q` and `V` from the other inputs and
//! writing `V` values (`V × V` for `M`, row-major); `dynamics_bench_dof` gives `V`. `M` is
//! `mass_matrix_into`, which leaves the blocks between two legs as `out` has them (its caller
//! keeps a matrix for it, zeroed once, as Pinocchio's `crba` keeps `data.M`); `fd` reads the
//! torques from the third input (NaN where M is not positive definite), `Minv` writes `M⁻¹`;
//! `tau_batch` and `fd_batch` take [`HORIZON`] states a call, as the fixed robots' do (`M_batch`,
//! `h_batch`, `Minv_batch`, `dtau_batch` in [`batches`]). And the first derivatives of
//! `FloatingDynamicsDerivatives<Q, V>`: `dtau` (`∂τ/∂q` along the tangent, then `∂τ/∂v`:
//! 2 V × V) and `dqdd` (`∂a/∂q`, `∂a/∂v`, `∂a/∂τ`: 3 V × V, NaN where M is not positive
//! definite; its third input `tau`). `contact_fd`: `FloatingContacts::contact_dynamics` with every
//! frame of `FloatingKinematics` held, `a` (V) then `λ` (3 per frame); `Y` in
//! [`super::floating_regressor`].

mod batches;

use super::batch::{results, states, HORIZON};
use super::{input, output, output_matrix, Function, Robot};
use dynamics_runtime::{
    FloatingContacts, FloatingDynamics, FloatingDynamicsBatch, FloatingDynamicsDerivatives,
    NotPositiveDefinite,
};

/// The timed functions of one robot type on a free-flying base, as C functions.
struct Floating<R, const Q: usize, const V: usize>(core::marker::PhantomData<R>);

impl<R: FloatingDynamicsDerivatives<Q, V> + Default, const Q: usize, const V: usize>
    Floating<R, Q, V>
{
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
        // SAFETY: the contract of `Function` (room for V × V values at `out`, which holds
        // `f64`s, so it is aligned for them).
        unsafe {
            let m = &mut *out.cast::<[[f64; V]; V]>();
            R::default().mass_matrix_into(input::<Q>(q), m);
        }
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
            _ => {
                return Self::forward_and_batch(function)
                    .or_else(|| Self::derivatives(function))
                    .or_else(|| batches::Batches::<R, Q, V>::get(function))
            }
        })
    }
}

/// The forward dynamics, `M⁻¹` and the batch rows.
impl<R: FloatingDynamics<Q, V> + Default, const Q: usize, const V: usize> Floating<R, Q, V> {
    unsafe extern "C" fn forward(q: *const f64, v: *const f64, tau: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (V torques at `tau`).
        unsafe {
            let a = R::default().forward_dynamics(input::<Q>(q), input(v), input(tau));
            output(out, a.unwrap_or([f64::NAN; V]));
        }
    }

    unsafe extern "C" fn mass_inverse(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (room for V × V values at `out`).
        unsafe {
            let inverse = R::default().mass_matrix_inverse(input::<Q>(q));
            output_matrix(out, inverse.unwrap_or([[f64::NAN; V]; V]));
        }
    }

    unsafe extern "C" fn tau_batch(q: *const f64, v: *const f64, a: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, `HORIZON` times over (`HORIZON × Q` values at
        // `q`).
        unsafe {
            let out = results::<[f64; V]>(out);
            R::default().inverse_dynamics_batch(states::<Q>(q), states(v), states(a), out);
        }
    }

    unsafe extern "C" fn forward_batch(
        q: *const f64,
        v: *const f64,
        tau: *const f64,
        out: *mut f64,
    ) {
        let mut a: [Result<[f64; V], NotPositiveDefinite>; HORIZON] = [Ok([0.0; V]); HORIZON];
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe {
            R::default().forward_dynamics_batch(states::<Q>(q), states(v), states(tau), &mut a);
            for (o, r) in results::<[f64; V]>(out).iter_mut().zip(a) {
                *o = r.unwrap_or([f64::NAN; V]);
            }
        }
    }

    fn forward_and_batch(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"fd" => Self::forward,
            b"Minv" => Self::mass_inverse,
            b"tau_batch" => Self::tau_batch,
            b"fd_batch" => Self::forward_batch,
            _ => return None,
        })
    }
}

/// The first derivatives.
impl<R: FloatingDynamicsDerivatives<Q, V> + Default, const Q: usize, const V: usize>
    Floating<R, Q, V>
{
    unsafe extern "C" fn inverse_derivatives(
        q: *const f64,
        v: *const f64,
        a: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (room for 2 V × V values at `out`).
        unsafe {
            let d = R::default().inverse_dynamics_derivatives(input::<Q>(q), input(v), input(a));
            output_matrix(out, d.dtau_dq);
            output_matrix(out.add(V * V), d.dtau_dqd);
        }
    }

    unsafe extern "C" fn forward_derivatives(
        q: *const f64,
        v: *const f64,
        tau: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (V forces at `tau`, room for 3 V × V values).
        unsafe {
            let d = R::default().forward_dynamics_derivatives(input::<Q>(q), input(v), input(tau));
            let nan = [[f64::NAN; V]; V];
            let blocks = d.map_or([nan; 3], |d| [d.dqdd_dq, d.dqdd_dqd, d.dqdd_dtau]);
            for (k, block) in blocks.into_iter().enumerate() {
                output_matrix(out.add(k * V * V), block);
            }
        }
    }

    fn derivatives(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"dtau" => Self::inverse_derivatives,
            b"dqdd" => Self::forward_derivatives,
            _ => return None,
        })
    }
}

/// The forward dynamics with every one of the `F` frames held (`contact_fd`).
pub(super) struct Contacts<R, const Q: usize, const V: usize, const F: usize>(
    core::marker::PhantomData<R>,
);

impl<R, const Q: usize, const V: usize, const F: usize> Contacts<R, Q, V, F>
where
    R: FloatingDynamicsDerivatives<Q, V> + FloatingContacts<Q, V, F> + Default,
{
    /// `FloatingContacts::contact_dynamics` with every frame in contact: `a` (V), then `λ`, a
    /// row of 3 per frame (NaN where there is no solution).
    unsafe extern "C" fn contact_fd(q: *const f64, v: *const f64, tau: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (V torques at `tau`, room for V + 3 F values).
        unsafe {
            let d = R::default().contact_dynamics(input::<Q>(q), input(v), input(tau), &[true; F]);
            let (a, forces) = d.map_or(([f64::NAN; V], [[f64::NAN; 3]; F]), |d| {
                (d.acceleration, d.forces)
            });
            output(out, a);
            super::output_rows(out.add(V), forces);
        }
    }

    pub(super) fn get(function: &[u8]) -> Option<Function> {
        match function {
            b"contact_fd" => Some(Self::contact_fd),
            _ => Floating::<R, Q, V>::get(function),
        }
    }
}

/// The entry of the robot `R` on a free-flying base: `V` generalized velocities, no base
/// parameters.
pub(super) fn floating<R, const Q: usize, const V: usize, const F: usize>(_: &R) -> Robot
where
    R: FloatingDynamicsDerivatives<Q, V> + FloatingContacts<Q, V, F> + Default,
{
    (V, 0, Contacts::<R, Q, V, F>::get)
}

#[cfg(test)]
pub(super) mod tests {
    use crate::{dynamics_bench_dof, dynamics_bench_function, Function};
    use dynamics_bench::{
        floating_contact_samples, floating_derivative_samples, floating_samples, scaled_error,
        AnymalB, Solo12, G1,
    };
    use dynamics_runtime::{FloatingContacts, FloatingDynamics, FloatingDynamicsDerivatives};

    pub(crate) fn lookup(robot: &str, function: &str) -> Option<Function> {
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
                if function == "M" {
                    // `mass_matrix_into` leaves the zeros between the legs as it finds them.
                    got[..V * V].fill(0.0);
                }
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
        check_forward(r, robot);
        for function in ["C", "fk", "J", "dqdd_batch"] {
            assert!(lookup(robot, function).is_none(), "{robot} {function}");
        }
        // Only Solo 12 is derived with its regressor.
        assert_eq!(lookup(robot, "Y").is_some(), robot == "solo12", "{robot} Y");
    }

    /// `fd` and `Minv` through the C ABI: the trait methods' bits, `fd` at Pinocchio's
    /// `τ = rnea(q, v, a)` its `a`, `M⁻¹ M = 1` with Pinocchio's `M`; `tau_batch` and `fd_batch`
    /// each state's single-state bits.
    fn check_forward<R, const Q: usize, const V: usize>(r: &R, robot: &str)
    where
        R: FloatingDynamics<Q, V>,
    {
        let samples = floating_samples::<Q, V>(robot);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        for s in &samples {
            let mut got = vec![f64::NAN; V * V + 1];
            let fd = lookup(robot, "fd").expect("fd");
            // SAFETY: Q values at q, V at v and tau, room for V outputs.
            unsafe { fd(s.q.as_ptr(), s.v.as_ptr(), s.tau.as_ptr(), got.as_mut_ptr()) };
            let want = r.forward_dynamics(&s.q, &s.v, &s.tau).expect("M > 0");
            assert_eq!(bits(&got[..V]), bits(&want), "{robot} fd");
            assert!(got[V..].iter().all(|x| x.is_nan()), "{robot} fd");
            assert!(
                scaled_error(&want, &s.a) < 1e-9,
                "{robot} fd from Pinocchio's a"
            );
            let minv = lookup(robot, "Minv").expect("Minv");
            // SAFETY: Q values at q, room for V × V outputs.
            unsafe { minv(s.q.as_ptr(), s.v.as_ptr(), s.a.as_ptr(), got.as_mut_ptr()) };
            let want = r.mass_matrix_inverse(&s.q).expect("M > 0");
            let want: Vec<f64> = want.iter().flatten().copied().collect();
            assert_eq!(bits(&got[..V * V]), bits(&want), "{robot} Minv");
            assert!(got[V * V].is_nan(), "{robot} Minv");
            let product: Vec<f64> = (0..V * V)
                .map(|ij| {
                    (0..V)
                        .map(|k| want[ij / V * V + k] * s.mass[k * V + ij % V])
                        .sum()
                })
                .collect();
            let identity: Vec<f64> = (0..V * V)
                .map(|ij| f64::from(u8::from(ij / V == ij % V)))
                .collect();
            assert!(scaled_error(&product, &identity) < 1e-9, "{robot} Minv M");
        }
        let horizon = crate::batch::HORIZON;
        let rows = |f: &dyn Fn(usize) -> Vec<f64>| (0..horizon).flat_map(f).collect::<Vec<f64>>();
        let at = |k: usize| &samples[k % samples.len()];
        let q = rows(&|k| at(k).q.to_vec());
        let (v, a) = (rows(&|k| at(k).v.to_vec()), rows(&|k| at(k).tau.to_vec()));
        for (batch, single) in [("tau_batch", "tau"), ("fd_batch", "fd")] {
            let mut out = vec![f64::NAN; horizon * V];
            let f = lookup(robot, batch).expect("a batch function");
            // SAFETY: HORIZON states in each input, room for as many outputs.
            unsafe { f(q.as_ptr(), v.as_ptr(), a.as_ptr(), out.as_mut_ptr()) };
            let one = lookup(robot, single).expect("its single-state function");
            for k in 0..horizon {
                let mut want = vec![f64::NAN; V];
                // SAFETY: one state in each input, room for its output.
                unsafe {
                    one(
                        q[k * Q..].as_ptr(),
                        v[k * V..].as_ptr(),
                        a[k * V..].as_ptr(),
                        want.as_mut_ptr(),
                    );
                }
                assert_eq!(
                    bits(&out[k * V..(k + 1) * V]),
                    bits(&want),
                    "{robot} {batch} {k}"
                );
            }
        }
    }

    /// Runs `f` on a thread with room: unoptimized, the G1's batches and derivatives (35
    /// coordinates) take more than a test thread's 2 MB of stack.
    pub(crate) fn with_room(f: impl FnOnce() + Send) {
        std::thread::scope(|s| {
            std::thread::Builder::new()
                .stack_size(64 << 20)
                .spawn_scoped(s, f)
                .expect("a thread")
                .join()
                .expect("the checks pass");
        });
    }

    /// `contact_fd` through the C ABI: the trait method's bits (every frame in contact),
    /// nothing written past its output, and Pinocchio's `constraintDynamics` with every foot
    /// held (`<robot>_contact_fd.json`) to 1e-9, the frames the same feet in the same order.
    fn check_contacts<R, const Q: usize, const V: usize, const F: usize>(
        r: &R,
        robot: &str,
        names: [&str; F],
    ) where
        R: FloatingContacts<Q, V, F>,
    {
        let (frames, pinocchio) = floating_contact_samples::<V, F>(robot);
        assert_eq!(frames, names.map(str::to_owned), "{robot}");
        let f = lookup(robot, "contact_fd").expect("contact_fd");
        for (s, (a, lambda)) in floating_samples::<Q, V>(robot).iter().zip(pinocchio) {
            let d = r
                .contact_dynamics(&s.q, &s.v, &s.tau, &[true; F])
                .expect("independent contacts");
            let want: Vec<f64> = d
                .acceleration
                .iter()
                .chain(d.forces.iter().flatten())
                .copied()
                .collect();
            let mut got = vec![f64::NAN; V + 3 * F + 1];
            // SAFETY: Q values at q, V at v and tau, room for V + 3 F outputs and one more.
            unsafe { f(s.q.as_ptr(), s.v.as_ptr(), s.tau.as_ptr(), got.as_mut_ptr()) };
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
            assert_eq!(bits(&got[..want.len()]), bits(&want), "{robot} contact_fd");
            assert!(got[want.len()].is_nan(), "{robot} contact_fd");
            let expected: Vec<f64> = a.iter().chain(lambda.iter().flatten()).copied().collect();
            let error = scaled_error(&want, &expected);
            assert!(error < 1e-9, "{robot} contact_fd: {error:e} from Pinocchio");
        }
    }

    #[test]
    fn contact_fd_through_the_c_abi_equals_the_trait_method_and_pinocchio() {
        with_room(|| {
            check_contacts(&Solo12, "solo12", Solo12::FRAME_NAMES);
            check_contacts(&AnymalB, "anymal_b", AnymalB::FRAME_NAMES);
        });
    }

    #[test]
    fn the_floating_robots_through_the_c_abi_equal_the_trait_methods_and_pinocchio() {
        with_room(|| {
            check_floating(&Solo12, "solo12");
            check_floating(&AnymalB, "anymal_b");
            check_floating(&G1, "g1_29dof");
        });
    }

    /// `dtau` and `dqdd` through the C ABI: the trait methods' bits, nothing written past their
    /// output, and Pinocchio's derivatives (the data) to 1e-9.
    fn check_floating_derivatives<R, const Q: usize, const V: usize>(r: &R, robot: &str)
    where
        R: FloatingDynamicsDerivatives<Q, V>,
    {
        let states = floating_samples::<Q, V>(robot);
        for (s, d) in states.iter().zip(floating_derivative_samples::<V>(robot)) {
            let inverse = r.inverse_dynamics_derivatives(&s.q, &s.v, &s.a);
            let forward = r
                .forward_dynamics_derivatives(&s.q, &s.v, &d.tau)
                .expect("M is positive definite");
            let flat = |ms: &[[[f64; V]; V]]| -> Vec<f64> {
                ms.iter().flatten().flatten().copied().collect()
            };
            let checks = [
                (
                    "dtau",
                    s.a,
                    flat(&[inverse.dtau_dq, inverse.dtau_dqd]),
                    &d.inverse,
                ),
                (
                    "dqdd",
                    d.tau,
                    flat(&[forward.dqdd_dq, forward.dqdd_dqd, forward.dqdd_dtau]),
                    &d.forward,
                ),
            ];
            for (function, third, want, pinocchio) in checks {
                let f = lookup(robot, function).expect("a floating robot's derivatives");
                let mut got = vec![f64::NAN; 3 * V * V + 1];
                // SAFETY: Q values at q, V at v and the third, room for 3 V × V and one more.
                unsafe { f(s.q.as_ptr(), s.v.as_ptr(), third.as_ptr(), got.as_mut_ptr()) };
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                assert_eq!(bits(&got[..want.len()]), bits(&want), "{robot} {function}");
                assert!(
                    got[want.len()..].iter().all(|x| x.is_nan()),
                    "{robot} {function}"
                );
                let error = scaled_error(&want, pinocchio);
                assert!(error < 1e-9, "{robot} {function}: {error:e} from Pinocchio");
            }
        }
    }

    #[test]
    fn the_floating_derivatives_through_the_c_abi_equal_the_trait_methods_and_pinocchio() {
        with_room(|| {
            check_floating_derivatives(&Solo12, "solo12");
            check_floating_derivatives(&AnymalB, "anymal_b");
            check_floating_derivatives(&G1, "g1_29dof");
        });
    }
}
