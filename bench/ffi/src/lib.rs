//! The generated dynamics of the four benchmark robots behind a C ABI, so that the Pinocchio
//! benchmark (`bench/pinocchio/bench.cpp`) can load them (`dlopen`) and time both sides in one
//! process, batch by batch in turn: the neighbours' load on this shared machine then slows both
//! sides alike, where two programs run one after the other see different spells.
//!
//! One entry point, [`dynamics_bench_function`], looks up a function by robot and name; every
//! function has the signature [`Function`].

use core::ffi::{c_char, CStr};
use dynamics_bench::{Puma560, Random5, Stanford, Ur5, DOF};
use dynamics_runtime::Dynamics;

/// `f(q, qd, qdd, out)`: reads `DOF` values from each input it uses and writes its output to
/// `out`, row-major: `DOF × DOF` values for `M` and `C`, `DOF` for the others.
pub type Function = unsafe extern "C" fn(*const f64, *const f64, *const f64, *mut f64);

/// Reads `DOF` values.
///
/// # Safety
/// `p` points to `DOF` readable `f64`s.
unsafe fn input(p: *const f64) -> [f64; DOF] {
    // SAFETY: the caller's contract.
    unsafe { p.cast::<[f64; DOF]>().read_unaligned() }
}

/// Writes `values`.
///
/// # Safety
/// `out` points to room for `N` `f64`s.
unsafe fn output<const N: usize>(out: *mut f64, values: [f64; N]) {
    // SAFETY: the caller's contract.
    unsafe { out.cast::<[f64; N]>().write_unaligned(values) }
}

/// The five timed functions of one robot type, as C functions.
struct Functions<R>(core::marker::PhantomData<R>);

impl<R: Dynamics<DOF> + Default> Functions<R> {
    unsafe extern "C" fn tau(q: *const f64, qd: *const f64, qdd: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let tau = R::default().inverse_dynamics(&input(q), &input(qd), &input(qdd));
            output(out, tau);
        }
    }

    unsafe extern "C" fn mass(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().mass_matrix(&input(q)).concat_rows()) }
    }

    unsafe extern "C" fn gravity(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().gravity_torques(&input(q))) }
    }

    unsafe extern "C" fn coriolis(q: *const f64, qd: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let c = R::default().coriolis_matrix(&input(q), &input(qd));
            output(out, c.concat_rows());
        }
    }

    unsafe extern "C" fn bias(q: *const f64, qd: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().bias_torques(&input(q), &input(qd))) }
    }

    fn get(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"tau" => Self::tau,
            b"M" => Self::mass,
            b"g" => Self::gravity,
            b"C" => Self::coriolis,
            b"h" => Self::bias,
            _ => return None,
        })
    }
}

/// A `DOF × DOF` matrix as its rows one after the other.
trait ConcatRows {
    fn concat_rows(self) -> [f64; DOF * DOF];
}

impl ConcatRows for [[f64; DOF]; DOF] {
    fn concat_rows(self) -> [f64; DOF * DOF] {
        core::array::from_fn(|k| self[k / DOF][k % DOF])
    }
}

/// The function `function` (`tau`, `M`, `g`, `C` or `h`, as in `timings`) of `robot`
/// (`puma560`, `stanford`, `ur5` or `random5`), or null for an unknown name.
///
/// # Safety
/// Both arguments are null or NUL-terminated strings.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_function(
    robot: *const c_char,
    function: *const c_char,
) -> Option<Function> {
    if robot.is_null() || function.is_null() {
        return None;
    }
    // SAFETY: the caller's contract.
    let (robot, function) = unsafe { (CStr::from_ptr(robot), CStr::from_ptr(function)) };
    let function = function.to_bytes();
    match robot.to_bytes() {
        b"puma560" => Functions::<Puma560>::get(function),
        b"stanford" => Functions::<Stanford>::get(function),
        b"ur5" => Functions::<Ur5>::get(function),
        b"random5" => Functions::<Random5>::get(function),
        _ => None,
    }
}

/// The number of joints of every robot, for the caller to check against its models.
#[no_mangle]
pub extern "C" fn dynamics_bench_dof() -> usize {
    DOF
}

#[cfg(test)]
mod tests {
    use super::*;
    use dynamics_bench::{samples, ROBOTS};

    fn lookup(robot: &str, function: &str) -> Option<Function> {
        let robot = std::ffi::CString::new(robot).unwrap();
        let function = std::ffi::CString::new(function).unwrap();
        // SAFETY: two NUL-terminated strings.
        unsafe { dynamics_bench_function(robot.as_ptr(), function.as_ptr()) }
    }

    /// `function` of `robot` called through the C ABI on a sample, its output padded to 36.
    fn call(robot: &str, function: &str, s: &dynamics_bench::Sample) -> [f64; DOF * DOF] {
        let f = lookup(robot, function).expect("a known function");
        let mut out = [f64::NAN; DOF * DOF];
        // SAFETY: DOF inputs each, room for DOF × DOF outputs.
        unsafe {
            f(
                s.q.as_ptr(),
                s.qd.as_ptr(),
                s.qdd.as_ptr(),
                out.as_mut_ptr(),
            )
        };
        out
    }

    fn direct<R: Dynamics<DOF>>(r: &R, function: &str, s: &dynamics_bench::Sample) -> Vec<f64> {
        match function {
            "tau" => r.inverse_dynamics(&s.q, &s.qd, &s.qdd).to_vec(),
            "M" => r.mass_matrix(&s.q).concat_rows().to_vec(),
            "g" => r.gravity_torques(&s.q).to_vec(),
            "C" => r.coriolis_matrix(&s.q, &s.qd).concat_rows().to_vec(),
            "h" => r.bias_torques(&s.q, &s.qd).to_vec(),
            _ => unreachable!(),
        }
    }

    #[test]
    fn every_function_through_the_c_abi_equals_the_trait_method() {
        for robot in ROBOTS {
            for s in samples(robot).iter().take(3) {
                for function in ["tau", "M", "g", "C", "h"] {
                    let want = match robot {
                        "puma560" => direct(&Puma560, function, s),
                        "stanford" => direct(&Stanford, function, s),
                        "ur5" => direct(&Ur5, function, s),
                        _ => direct(&Random5, function, s),
                    };
                    let got = call(robot, function, s);
                    assert_eq!(&got[..want.len()], &want[..], "{robot} {function}");
                    // Nothing is written past the output.
                    assert!(
                        got[want.len()..].iter().all(|x| x.is_nan()),
                        "{robot} {function}"
                    );
                }
            }
        }
    }

    #[test]
    fn inverse_dynamics_through_the_c_abi_matches_the_reference_data() {
        for robot in ROBOTS {
            for s in samples(robot) {
                let tau = call(robot, "tau", &s);
                let err = dynamics_bench::scaled_error(&tau[..DOF], &s.tau);
                assert!(err < 1e-9, "{robot}: {err:e}");
            }
        }
    }

    #[test]
    fn unknown_names_and_null_give_null() {
        assert!(lookup("puma560", "qdd").is_none());
        assert!(lookup("puma", "tau").is_none());
        assert!(lookup("", "").is_none());
        // SAFETY: null is allowed.
        let none = unsafe { dynamics_bench_function(core::ptr::null(), c"tau".as_ptr()) };
        assert!(none.is_none());
        assert_eq!(dynamics_bench_dof(), 6);
    }
}
