//! The simplified models (the family `Simplified`) of the robots whose derives ask for them
//! ([`dynamics_bench::SIMPLIFIED`]): `tau_simplified`, `M_simplified` and `g_simplified`, with
//! the signatures and layouts of `tau`, `M` and `g`; and, for the C++ side's check against
//! Pinocchio, each output's proven bounds ([`dynamics_bench_simplified_bounds`]) and the
//! envelope they hold over ([`dynamics_bench_simplified_envelope`]).

use super::{input, output, output_matrix, Function};
use core::ffi::{c_char, CStr};
use core::marker::PhantomData;
use dynamics_bench::{Panda, Puma560};
use dynamics_codegen::{Method, SimplifiedEquations};
use dynamics_runtime::DynamicsSimplified;
use std::sync::OnceLock;

/// The simplified functions of one `N`-joint robot type, as C functions.
struct Functions<R, const N: usize>(PhantomData<R>);

impl<R: DynamicsSimplified<N> + Default, const N: usize> Functions<R, N> {
    unsafe extern "C" fn tau(q: *const f64, qd: *const f64, qdd: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let r = R::default();
            output(
                out,
                r.inverse_dynamics_simplified(input(q), input(qd), input(qdd)),
            );
        }
    }

    unsafe extern "C" fn mass(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output_matrix(out, R::default().mass_matrix_simplified(input(q))) }
    }

    unsafe extern "C" fn gravity(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().gravity_torques_simplified(input(q))) }
    }

    fn get(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"tau_simplified" => Self::tau,
            b"M_simplified" => Self::mass,
            b"g_simplified" => Self::gravity,
            _ => return None,
        })
    }
}

/// The simplified function `function` of `robot`, if the robot has simplified models.
pub(crate) fn get(robot: &[u8], function: &[u8]) -> Option<Function> {
    match robot {
        b"puma560" => Functions::<Puma560, 6>::get(function),
        b"panda" => Functions::<Panda, 7>::get(function),
        _ => None,
    }
}

/// The pruned equations of `robot`, built once (the Panda's take about a second).
fn equations(robot: &[u8]) -> Option<&'static SimplifiedEquations> {
    static PUMA: OnceLock<Option<SimplifiedEquations>> = OnceLock::new();
    static PANDA: OnceLock<Option<SimplifiedEquations>> = OnceLock::new();
    let (cell, name) = match robot {
        b"puma560" => (&PUMA, "puma560"),
        b"panda" => (&PANDA, "panda"),
        _ => return None,
    };
    let build = || dynamics_bench::simplified(name).and_then(|eq| eq.simplified);
    cell.get_or_init(build).as_ref()
}

/// The bounds of `function`'s elements, row-major for `M_simplified`.
fn bounds(s: &SimplifiedEquations, function: &[u8]) -> Option<Vec<f64>> {
    let method = match function {
        b"tau_simplified" => Method::InverseDynamicsSimplified,
        b"M_simplified" => Method::MassMatrixSimplified,
        b"g_simplified" => Method::GravityTorquesSimplified,
        _ => return None,
    };
    Some(s.output(method)?.bounds.all().map(|b| b.bound).collect())
}

/// Reads a C string.
///
/// # Safety
/// `p` is null or a NUL-terminated string.
unsafe fn bytes<'a>(p: *const c_char) -> Option<&'a [u8]> {
    // SAFETY: the caller's contract.
    (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_bytes())
}

/// Writes the proven bound of each element of `robot`'s `function` (`tau_simplified`,
/// `M_simplified`, row-major, or `g_simplified`) to `out`, 0 for an output left exact, and
/// returns how many: n or n × n, 0 (nothing written) for a robot or function without them.
///
/// # Safety
/// `robot` and `function` are null or NUL-terminated strings; `out` has room for n × n values.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_simplified_bounds(
    robot: *const c_char,
    function: *const c_char,
    out: *mut f64,
) -> usize {
    // SAFETY: the caller's contract.
    let (Some(robot), Some(function)) = (unsafe { bytes(robot) }, unsafe { bytes(function) })
    else {
        return 0;
    };
    let Some(values) = equations(robot).and_then(|s| bounds(s, function)) else {
        return 0;
    };
    for (i, v) in values.iter().enumerate() {
        // SAFETY: room for n × n values, at least as many as these.
        unsafe { out.add(i).write(*v) };
    }
    values.len()
}

/// Writes the envelope of `robot`'s simplified models to `out`, per joint its lowest and
/// highest position, largest speed and largest acceleration (4 n values), and returns n; 0
/// (nothing written) for a robot without simplified models.
///
/// # Safety
/// `robot` is null or a NUL-terminated string; `out` has room for 4 n values.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_simplified_envelope(
    robot: *const c_char,
    out: *mut f64,
) -> usize {
    // SAFETY: the caller's contract.
    let Some(s) = unsafe { bytes(robot) }.and_then(equations) else {
        return 0;
    };
    let joints = &s.request.envelope.joints;
    for (i, j) in joints.iter().enumerate() {
        let values = [j.lower, j.upper, j.speed, j.acceleration];
        // SAFETY: room for 4 n values.
        unsafe { output(out.add(4 * i), values) };
    }
    joints.len()
}

#[cfg(test)]
mod tests {
    use super::*;
    use dynamics_bench::samples;
    use dynamics_codegen::State;

    /// The derive's simplified outputs equal the pruned graph of the request that
    /// `dynamics_bench::simplification` restates, at the reference samples: the bounds given
    /// to the C++ side are those of the code it times.
    fn same_request<R: DynamicsSimplified<N> + Default, const N: usize>(robot: &str) {
        let eq = dynamics_bench::simplified(robot).expect("simplified");
        let s = eq.simplified.as_ref().expect("simplified");
        for sample in samples::<N>(robot) {
            let values = eq.evaluate(&State {
                fields: &[],
                q: &sample.q,
                qd: &sample.qd,
                qdd: &sample.qdd,
                tau: &[],
            });
            let r = R::default();
            let derived = [
                r.inverse_dynamics_simplified(&sample.q, &sample.qd, &sample.qdd)
                    .to_vec(),
                r.mass_matrix_simplified(&sample.q).concat(),
                r.gravity_torques_simplified(&sample.q).to_vec(),
            ];
            let graph = [
                Method::InverseDynamicsSimplified,
                Method::MassMatrixSimplified,
                Method::GravityTorquesSimplified,
            ]
            .map(|m| {
                s.output(m)
                    .expect("simplified")
                    .elements
                    .all()
                    .copied()
                    .collect::<Vec<_>>()
            });
            for (derived, graph) in derived.iter().zip(&graph) {
                for (x, id) in derived.iter().zip(graph) {
                    let y = values.of(*id);
                    assert!((x - y).abs() <= 1e-9 * y.abs().max(1.0), "{robot}: {x} {y}");
                }
            }
        }
    }

    #[test]
    fn the_restated_requests_are_the_derives() {
        same_request::<Puma560, 6>("puma560");
        same_request::<Panda, 7>("panda");
    }

    #[test]
    fn bounds_and_envelopes_through_the_c_abi() {
        let mut out = [f64::NAN; 49];
        // SAFETY: NUL-terminated strings, room for 49 values.
        let n = unsafe {
            dynamics_bench_simplified_bounds(
                c"panda".as_ptr(),
                c"M_simplified".as_ptr(),
                out.as_mut_ptr(),
            )
        };
        assert_eq!(n, 49);
        // SAFETY: as above.
        let n = unsafe {
            dynamics_bench_simplified_bounds(
                c"puma560".as_ptr(),
                c"g_simplified".as_ptr(),
                out.as_mut_ptr(),
            )
        };
        assert_eq!(n, 6);
        assert!(
            out[..6].iter().all(|b| *b >= 0.0) && out[1] > 0.0,
            "{out:?}"
        );
        // SAFETY: as above.
        let n =
            unsafe { dynamics_bench_simplified_envelope(c"puma560".as_ptr(), out.as_mut_ptr()) };
        assert_eq!((n, &out[..4]), (6, &[-2.5, 2.0, 2.0, 5.0][..]));
        // SAFETY: as above; null allowed.
        let none = unsafe {
            dynamics_bench_simplified_bounds(
                c"ur5".as_ptr(),
                c"tau_simplified".as_ptr(),
                out.as_mut_ptr(),
            ) + dynamics_bench_simplified_envelope(core::ptr::null(), out.as_mut_ptr())
        };
        assert_eq!(none, 0);
    }
}
