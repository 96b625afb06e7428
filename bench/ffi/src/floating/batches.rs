//! The batch rows of a robot on a free-flying base beside `tau_batch` and `fd_batch`
//! ([`super`]): `M_batch`, `h_batch` and `Minv_batch` of `FloatingDynamicsBatch`,
//! `dtau_batch` of `FloatingDynamicsDerivativesBatch`. [`HORIZON`] states a call, state after
//! state (`Q` values of `q`, `V` of `v` and `a` each); each state's output is the single-state
//! function's, one after the other: `M` and `Minv` `V × V` row-major (`Minv` NaN where M is not
//! positive definite), `h` `V`, `dtau` `∂τ/∂q` then `∂τ/∂v` (2 V × V).

use crate::batch::{results, states, HORIZON};
use crate::Function;
use dynamics_runtime::{
    FloatingDynamicsBatch, FloatingDynamicsDerivatives, FloatingDynamicsDerivativesBatch,
    InverseDynamicsDerivatives, NotPositiveDefinite,
};

/// The batch rows of one robot type on a free-flying base, as C functions.
pub(super) struct Batches<R, const Q: usize, const V: usize>(core::marker::PhantomData<R>);

impl<R: FloatingDynamicsDerivatives<Q, V> + Default, const Q: usize, const V: usize>
    Batches<R, Q, V>
{
    unsafe extern "C" fn mass_batch(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, `HORIZON` times over (`HORIZON × Q` values at
        // `q`, room for `HORIZON × V × V` at `out`).
        unsafe { R::default().mass_matrix_batch(states::<Q>(q), results::<[[f64; V]; V]>(out)) }
    }

    unsafe extern "C" fn bias_batch(q: *const f64, v: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe {
            let out = results::<[f64; V]>(out);
            R::default().bias_forces_batch(states::<Q>(q), states::<V>(v), out);
        }
    }

    unsafe extern "C" fn mass_inverse_batch(
        q: *const f64,
        _: *const f64,
        _: *const f64,
        out: *mut f64,
    ) {
        // A group of lanes' states a call, so that the results (`Result` is not `repr(C)`) stay
        // in the first-level cache until they are copied out; eight fills both lane widths.
        const GROUP: usize = 8;
        let mut inverses: [Result<[[f64; V]; V], NotPositiveDefinite>; GROUP] =
            [Err(NotPositiveDefinite); GROUP];
        // SAFETY: the contract of `Function`, `HORIZON` times over.
        unsafe {
            let (q, out) = (states::<Q>(q), results::<[[f64; V]; V]>(out));
            for at in (0..HORIZON).step_by(GROUP) {
                let range = at..HORIZON.min(at + GROUP);
                let k = range.len();
                R::default().mass_matrix_inverse_batch(&q[range.clone()], &mut inverses[..k]);
                for (o, r) in out[range].iter_mut().zip(&inverses[..k]) {
                    *o = r.unwrap_or([[f64::NAN; V]; V]);
                }
            }
        }
    }

    unsafe extern "C" fn inverse_derivatives_batch(
        q: *const f64,
        v: *const f64,
        a: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function`, `HORIZON` times over; the derivatives are
        // `repr(C)`, `[dtau_dq, dtau_dqd]` as the output's `2 × V × V` values of a state.
        unsafe {
            let out = results::<InverseDynamicsDerivatives<[[f64; V]; V]>>(out);
            R::default().inverse_dynamics_derivatives_batch(
                states::<Q>(q),
                states::<V>(v),
                states::<V>(a),
                out,
            );
        }
    }

    /// The batch row named `function`.
    pub(super) fn get(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"M_batch" => Self::mass_batch,
            b"h_batch" => Self::bias_batch,
            b"Minv_batch" => Self::mass_inverse_batch,
            b"dtau_batch" => Self::inverse_derivatives_batch,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::batch::HORIZON;
    use crate::floating::tests::{lookup, with_room};
    use dynamics_bench::floating_samples;

    /// Each state's output of a batch row has the bits of the single-state function's through
    /// the C ABI (`M` written into a zeroed matrix, as its blocks between the legs stay zero),
    /// and nothing is written past the last state's.
    fn check<const Q: usize, const V: usize>(robot: &str) {
        let samples = floating_samples::<Q, V>(robot);
        let rows = |f: &dyn Fn(usize) -> Vec<f64>| (0..HORIZON).flat_map(f).collect::<Vec<f64>>();
        let at = |k: usize| &samples[k % samples.len()];
        let q = rows(&|k| at(k).q.to_vec());
        let (v, a) = (rows(&|k| at(k).v.to_vec()), rows(&|k| at(k).a.to_vec()));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        for (batch, single, size) in [
            ("M_batch", "M", V * V),
            ("h_batch", "h", V),
            ("Minv_batch", "Minv", V * V),
            ("dtau_batch", "dtau", 2 * V * V),
        ] {
            let f = lookup(robot, batch).expect("a floating batch row");
            let mut out = vec![f64::NAN; HORIZON * size + 1];
            // SAFETY: HORIZON states in each input, room for as many outputs and one more.
            unsafe { f(q.as_ptr(), v.as_ptr(), a.as_ptr(), out.as_mut_ptr()) };
            assert!(out[HORIZON * size].is_nan(), "{robot} {batch} writes past");
            let one = lookup(robot, single).expect("its single-state function");
            for k in 0..HORIZON {
                let mut want = vec![0.0; size];
                // SAFETY: one state in each input, room for its output.
                unsafe {
                    one(
                        q[k * Q..].as_ptr(),
                        v[k * V..].as_ptr(),
                        a[k * V..].as_ptr(),
                        want.as_mut_ptr(),
                    );
                }
                let got = &out[k * size..(k + 1) * size];
                assert_eq!(bits(got), bits(&want), "{robot} {batch} {k}");
            }
        }
    }

    #[test]
    fn the_floating_batch_rows_equal_the_single_state_functions() {
        with_room(|| {
            check::<19, 18>("solo12");
            check::<19, 18>("anymal_b");
            check::<36, 35>("g1_29dof");
        });
    }
}
