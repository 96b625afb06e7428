//! The batch functions: [`HORIZON`] states a call through the `_batch` methods, `tau_batch`,
//! `M_batch`, `fd_batch`, `dtau_batch` and `dqdd_batch`, as a model-predictive controller
//! evaluates the knots of its horizon. Each input holds `HORIZON × n` values, state after state (row k is state k);
//! the output is each state's output, as the single-state function writes it, one after the
//! other (NaN for a failed solve).

use super::{Function, Functions, Timed};
use dynamics_runtime::{
    DynamicsBatch, DynamicsDerivativesBatch, ForwardDynamicsDerivatives,
    InverseDynamicsDerivatives, NotPositiveDefinite,
};

/// The number of states of a batch call.
pub const HORIZON: usize = 100;

/// One state's forward dynamics and derivatives, or the failed solve.
type Forward<const N: usize> =
    Result<ForwardDynamicsDerivatives<[f64; N], [[f64; N]; N]>, NotPositiveDefinite>;

/// `HORIZON` states of `N` values.
///
/// # Safety
/// `p` points to `HORIZON × N` readable `f64`s.
pub(super) unsafe fn states<'a, const N: usize>(p: *const f64) -> &'a [[f64; N]; HORIZON] {
    // SAFETY: the caller's contract; `f64`s are aligned for arrays of them.
    unsafe { &*p.cast::<[[f64; N]; HORIZON]>() }
}

/// Room for `HORIZON` results of type `O`.
///
/// # Safety
/// `p` points to room for `HORIZON` values of `O`, made of `f64`s.
pub(super) unsafe fn results<'a, O>(p: *mut f64) -> &'a mut [O; HORIZON] {
    // SAFETY: the caller's contract.
    unsafe { &mut *p.cast::<[O; HORIZON]>() }
}

impl<R: Timed<N, B>, const N: usize, const B: usize> Functions<R, N, B> {
    unsafe extern "C" fn tau_batch(q: *const f64, qd: *const f64, qdd: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe {
            let out = results::<[f64; N]>(out);
            R::default().inverse_dynamics_batch(states(q), states(qd), states(qdd), out);
        }
    }

    unsafe extern "C" fn mass_batch(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe { R::default().mass_matrix_batch(states(q), results::<[[f64; N]; N]>(out)) }
    }

    unsafe extern "C" fn forward_batch(
        q: *const f64,
        qd: *const f64,
        tau: *const f64,
        out: *mut f64,
    ) {
        let mut qdd: [Result<[f64; N], NotPositiveDefinite>; HORIZON] = [Ok([0.0; N]); HORIZON];
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe {
            R::default().forward_dynamics_batch(states(q), states(qd), states(tau), &mut qdd);
            let out = results::<[f64; N]>(out);
            for (o, r) in out.iter_mut().zip(qdd) {
                *o = r.unwrap_or([f64::NAN; N]);
            }
        }
    }

    unsafe extern "C" fn inverse_derivatives_batch(
        q: *const f64,
        qd: *const f64,
        qdd: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function`, `HORIZON` times over; the derivatives are
        // `repr(C)`, `[dtau_dq, dtau_dqd]` as the output's `2 × N × N` values of a state.
        unsafe {
            let out = results::<InverseDynamicsDerivatives<[[f64; N]; N]>>(out);
            R::default().inverse_dynamics_derivatives_batch(
                states(q),
                states(qd),
                states(qdd),
                out,
            );
        }
    }

    unsafe extern "C" fn forward_derivatives_batch(
        q: *const f64,
        qd: *const f64,
        tau: *const f64,
        out: *mut f64,
    ) {
        // Eight states a call (a group of `F64x8` lanes), so that the results stay in the
        // first-level cache until they are copied out (`Result` is not `repr(C)`).
        const GROUP: usize = 8;
        let mut derivatives: [Forward<N>; GROUP] = [Err(NotPositiveDefinite); GROUP];
        // SAFETY: the contract of `Function`, `HORIZON` times over: each state's output is
        // `dqdd`'s, `∂q̈/∂q`, `∂q̈/∂q̇` and `∂q̈/∂τ` (3 × N × N values).
        unsafe {
            let (q, qd, tau) = (states::<N>(q), states::<N>(qd), states::<N>(tau));
            let out = results::<[[[f64; N]; N]; 3]>(out);
            for at in (0..HORIZON).step_by(GROUP) {
                let k = GROUP.min(HORIZON - at);
                let range = at..at + k;
                R::default().forward_dynamics_derivatives_batch(
                    &q[range.clone()],
                    &qd[range.clone()],
                    &tau[range.clone()],
                    &mut derivatives[..k],
                );
                for (o, d) in out[range].iter_mut().zip(&derivatives[..k]) {
                    let nan = [[f64::NAN; N]; N];
                    *o = d.map_or([nan; 3], |d| [d.dqdd_dq, d.dqdd_dqd, d.dqdd_dtau]);
                }
            }
        }
    }

    /// The batch function named `function`.
    pub(super) fn get_batch(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"tau_batch" => Self::tau_batch,
            b"M_batch" => Self::mass_batch,
            b"fd_batch" => Self::forward_batch,
            b"dtau_batch" => Self::inverse_derivatives_batch,
            b"dqdd_batch" => Self::forward_derivatives_batch,
            _ => return None,
        })
    }
}

/// The number of states of a batch function's call, [`HORIZON`].
#[no_mangle]
pub extern "C" fn dynamics_bench_horizon() -> usize {
    HORIZON
}

#[cfg(test)]
mod tests {
    use super::HORIZON;
    use crate::{dynamics_bench_dof, dynamics_bench_function, Function};
    use dynamics_bench::{samples, ROBOTS};

    fn lookup(robot: &str, function: &str) -> Function {
        let robot = std::ffi::CString::new(robot).unwrap();
        let function = std::ffi::CString::new(function).unwrap();
        // SAFETY: two NUL-terminated strings.
        unsafe { dynamics_bench_function(robot.as_ptr(), function.as_ptr()) }.unwrap()
    }

    /// Each state's output of a batch function has the bits of the single-state function's
    /// (`fd` and `dqdd` read the sample's `q̈` as torques).
    fn check<const N: usize>(robot: &str) {
        let s = samples::<N>(robot);
        let rows = |f: &dyn Fn(usize) -> [f64; N]| (0..HORIZON).flat_map(f).collect::<Vec<_>>();
        let (q, qd) = (rows(&|k| s[k % s.len()].q), rows(&|k| s[k % s.len()].qd));
        let qdd = rows(&|k| s[k % s.len()].qdd);
        for (batch, single, size) in [
            ("tau_batch", "tau", N),
            ("M_batch", "M", N * N),
            ("fd_batch", "fd", N),
            ("dtau_batch", "dtau", 2 * N * N),
            ("dqdd_batch", "dqdd", 3 * N * N),
        ] {
            let mut out = vec![0.0; HORIZON * size];
            // SAFETY: HORIZON states in each input, room for as many outputs.
            unsafe {
                lookup(robot, batch)(q.as_ptr(), qd.as_ptr(), qdd.as_ptr(), out.as_mut_ptr())
            };
            for k in 0..HORIZON {
                let mut one = vec![0.0; size];
                let at = k * N;
                // SAFETY: one state in each input, room for its output.
                unsafe {
                    lookup(robot, single)(
                        q[at..].as_ptr(),
                        qd[at..].as_ptr(),
                        qdd[at..].as_ptr(),
                        one.as_mut_ptr(),
                    );
                }
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                assert_eq!(
                    bits(&out[k * size..(k + 1) * size]),
                    bits(&one),
                    "{robot} {batch} {k}"
                );
            }
        }
    }

    #[test]
    fn batch_functions_equal_the_single_state_ones() {
        for robot in ROBOTS {
            let name = std::ffi::CString::new(robot).unwrap();
            // SAFETY: a NUL-terminated string.
            match unsafe { dynamics_bench_dof(name.as_ptr()) } {
                6 => check::<6>(robot),
                7 => check::<7>(robot),
                n => panic!("{robot}: {n} joints"),
            }
        }
    }
}
