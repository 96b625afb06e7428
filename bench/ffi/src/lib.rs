//! The generated dynamics of the benchmark robots behind a C ABI, so that the Pinocchio
//! benchmark (`bench/pinocchio/bench.cpp`) can load them (`dlopen`) and time both sides in one
//! process, batch by batch in turn: the neighbours' load on this shared machine then slows both
//! sides alike, where two programs run one after the other see different spells.
//!
//! One entry point, [`dynamics_bench_function`], looks up a function by robot and name; every
//! function has the signature [`Function`]; [`dynamics_bench_dof`] gives a robot's number of
//! joints. Beside the dynamics (`tau`, `M`, `g`, `C`, `h`), the kinematics: `fk` (the hand
//! pose), `J` (the hand's Jacobian in base axes) and `JtF` (the joint torques for a wrench in
//! base axes, `T = Jᵀ F`); the forward dynamics `fd` and `Minv` (M⁻¹), NaN where M is not
//! positive definite; the derivatives `dtau` (of inverse dynamics) and `dqdd` (of forward
//! dynamics, NaN where M is not positive definite); the joint torque regressor `Y`, the base
//! regressor `YB` and the base parameters `piB` ([`dynamics_bench_base_count`] of them); and
//! `tau_batch`, `M_batch`, `fd_batch`, `dtau_batch`, `dqdd_batch`: [`HORIZON`] states a call
//! (`batch`). For the robots with simplified models, `tau_simplified`, `M_simplified`, `g_simplified`, with
//! their proven bounds ([`dynamics_bench_simplified_bounds`]) and envelope (`simplified`).

mod batch;
mod floating;
mod floating_regressor;
mod simplified;
mod trees;

pub use batch::{dynamics_bench_horizon, HORIZON};
use core::ffi::{c_char, CStr};
use dynamics_bench::{
    AllegroHand, AnymalB, BaxterFreeFingers, Panda, Puma560, Random5, Solo12, Stanford, Ur5, Ur5Dh,
    Ur5Urdf, G1,
};
use dynamics_runtime::{DynamicsBaseParameters, DynamicsDerivatives, DynamicsRegressor};
use floating::floating;
pub use simplified::{dynamics_bench_simplified_bounds, dynamics_bench_simplified_envelope};
use trees::tree;

/// The generated traits a benchmark robot implements, with `N` joints and `B` base parameters.
pub trait Timed<const N: usize, const B: usize>:
    DynamicsDerivatives<N> + DynamicsRegressor<N> + DynamicsBaseParameters<N, B> + Default
{
}

impl<R, const N: usize, const B: usize> Timed<N, B> for R where
    R: DynamicsDerivatives<N> + DynamicsRegressor<N> + DynamicsBaseParameters<N, B> + Default
{
}

/// `f(q, qd, qdd, out)`: reads n values (the robot's number of joints, aligned `f64`s) from each input it uses
/// and writes its output to `out`, row-major: n × n values for `M` and `C`, the 3 × 4 rows
/// `[R | p]` for `fk`, 6 × n for `J`, `∂τ/∂q` then `∂τ/∂q̇` for `dtau` (2 n × n), `∂q̈/∂q`,
/// `∂q̈/∂q̇`, `∂q̈/∂τ` for `dqdd` (3 n × n), the n × 10 n rows of the regressor for `Y`
/// (row i: link 1's ten columns, then link 2's, ...: `Y[i][j][k]` at `(i n + j) 10 + k`, Pinocchio's
/// `computeJointTorqueRegressor` layout), the n × B rows of the base regressor for `YB`, the B
/// base parameters for `piB` (no input read), n for the others. `JtF` reads the wrench
/// `[fx, fy, fz, mx, my, mz]` (six values) from the third input, in place of `qdd`, and `fd` and
/// `dqdd` the joint torques `tau`. `M` is `mass_matrix_into`: on a tree it leaves the blocks
/// between the branches as `out` has them, so its caller keeps a matrix for it, zeroed once (as
/// Pinocchio's `crba` keeps `data.M`), rather than an array other functions write into. On a
/// free-flying base, `tau`, `M`, `h`, `g` alone, `q` of `NV + 1` values, n = `NV` elsewhere.
pub type Function = unsafe extern "C" fn(*const f64, *const f64, *const f64, *mut f64);

/// The `N` values at `p`, by reference as a caller's array is passed: a copy onto the stack,
/// made with overlapping vector moves (48 or 56 bytes), stalls the loads of a method that is
/// not inlined here (they cannot be forwarded from the overlapping stores).
///
/// # Safety
/// `p` points to `N` readable `f64`s, aligned, unchanged while the reference lives.
unsafe fn input<'a, const N: usize>(p: *const f64) -> &'a [f64; N] {
    // SAFETY: the caller's contract.
    unsafe { &*p.cast::<[f64; N]>() }
}

/// Writes `values`.
///
/// # Safety
/// `out` points to room for `N` `f64`s.
unsafe fn output<const N: usize>(out: *mut f64, values: [f64; N]) {
    // SAFETY: the caller's contract.
    unsafe { out.cast::<[f64; N]>().write_unaligned(values) }
}

/// The timed functions of one `N`-joint robot type, as C functions.
struct Functions<R, const N: usize, const B: usize>(core::marker::PhantomData<R>);

impl<R: DynamicsDerivatives<N> + Default, const N: usize, const B: usize> Functions<R, N, B> {
    unsafe extern "C" fn tau(q: *const f64, qd: *const f64, qdd: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let tau = R::default().inverse_dynamics(input(q), input(qd), input(qdd));
            output(out, tau);
        }
    }

    unsafe extern "C" fn mass(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (room for n × n values at `out`, which holds `f64`s,
        // so it is aligned for them).
        unsafe {
            let m = &mut *out.cast::<[[f64; N]; N]>();
            R::default().mass_matrix_into(input(q), m);
        }
    }

    unsafe extern "C" fn gravity(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().gravity_torques(input(q))) }
    }

    unsafe extern "C" fn coriolis(q: *const f64, qd: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let c = R::default().coriolis_matrix(input(q), input(qd));
            output_matrix(out, c);
        }
    }

    unsafe extern "C" fn bias(q: *const f64, qd: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output(out, R::default().bias_torques(input(q), input(qd))) }
    }

    unsafe extern "C" fn forward(q: *const f64, qd: *const f64, tau: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (n torques at `tau`).
        unsafe {
            let qdd = R::default().forward_dynamics(input(q), input(qd), input(tau));
            output(out, qdd.unwrap_or([f64::NAN; N]));
        }
    }

    unsafe extern "C" fn mass_inverse(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe {
            let inverse = R::default().mass_matrix_inverse(input(q));
            output_matrix(out, inverse.unwrap_or([[f64::NAN; N]; N]));
        }
    }

    unsafe extern "C" fn inverse_derivatives(
        q: *const f64,
        qd: *const f64,
        qdd: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (room for 2 n × n values at `out`).
        unsafe {
            let d = R::default().inverse_dynamics_derivatives(input(q), input(qd), input(qdd));
            output_matrix(out, d.dtau_dq);
            output_matrix(out.add(N * N), d.dtau_dqd);
        }
    }

    unsafe extern "C" fn forward_derivatives(
        q: *const f64,
        qd: *const f64,
        tau: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (n torques at `tau`, room for 3 n × n values at
        // `out`).
        unsafe {
            let d = R::default().forward_dynamics_derivatives(input(q), input(qd), input(tau));
            let nan = [[f64::NAN; N]; N];
            let blocks = d.map_or([nan; 3], |d| [d.dqdd_dq, d.dqdd_dqd, d.dqdd_dtau]);
            for (k, block) in blocks.into_iter().enumerate() {
                output_matrix(out.add(k * N * N), block);
            }
        }
    }

    /// The functions of the dynamics and their derivatives alone: a tree's (no hand frame,
    /// regressor or base parameters).
    fn dynamics(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"tau" => Self::tau,
            b"M" => Self::mass,
            b"g" => Self::gravity,
            b"C" => Self::coriolis,
            b"h" => Self::bias,
            b"fd" => Self::forward,
            b"Minv" => Self::mass_inverse,
            b"dtau" => Self::inverse_derivatives,
            b"dqdd" => Self::forward_derivatives,
            _ => return None,
        })
    }
}

impl<R: Timed<N, B>, const N: usize, const B: usize> Functions<R, N, B> {
    unsafe extern "C" fn hand_pose(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        let pose = R::default().hand_pose(input(q));
        let rows = core::array::from_fn(|i| {
            let r = pose.rotation[i];
            [r[0], r[1], r[2], pose.position[i]]
        });
        // SAFETY: the contract of `Function`.
        unsafe { output_rows::<4, 3>(out, rows) }
    }

    unsafe extern "C" fn jacobian(q: *const f64, _: *const f64, _: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function`.
        unsafe { output_rows(out, R::default().hand_jacobian_in_base(input(q))) }
    }

    unsafe extern "C" fn statics(q: *const f64, _: *const f64, wrench: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (six values at `wrench`).
        unsafe {
            let tau = R::default().joint_torques_for_base_wrench(input(q), input(wrench));
            output(out, tau);
        }
    }

    unsafe extern "C" fn regressor(q: *const f64, qd: *const f64, qdd: *const f64, out: *mut f64) {
        // SAFETY: the contract of `Function` (room for n × 10 n values at `out`).
        unsafe {
            // Written in place (`[i][j][k]` is at `(i n + j) 10 + k`), as Pinocchio writes its
            // `data.jointTorqueRegressor`. `out` holds `f64`s, so it is aligned for them.
            let y = &mut *out.cast::<[[[f64; 10]; N]; N]>();
            R::default().regressor_into(input(q), input(qd), input(qdd), y);
        }
    }

    unsafe extern "C" fn base_regressor(
        q: *const f64,
        qd: *const f64,
        qdd: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (room for n × B values at `out`, aligned for
        // `f64`s).
        unsafe {
            let y = &mut *out.cast::<[[f64; B]; N]>();
            R::default().base_regressor_into(input(q), input(qd), input(qdd), y);
        }
    }

    unsafe extern "C" fn base_parameters(
        _: *const f64,
        _: *const f64,
        _: *const f64,
        out: *mut f64,
    ) {
        // SAFETY: the contract of `Function` (room for B values at `out`).
        unsafe { output(out, R::default().base_parameters::<f64>()) }
    }

    fn get(function: &[u8]) -> Option<Function> {
        Some(match function {
            b"fk" => Self::hand_pose,
            b"J" => Self::jacobian,
            b"JtF" => Self::statics,
            b"Y" => Self::regressor,
            b"YB" => Self::base_regressor,
            b"piB" => Self::base_parameters,
            _ => return Self::dynamics(function).or_else(|| Self::get_batch(function)),
        })
    }
}

/// Writes the rows of an `N × N` matrix one after the other.
///
/// # Safety
/// `out` points to room for `N × N` `f64`s.
unsafe fn output_matrix<const N: usize>(out: *mut f64, m: [[f64; N]; N]) {
    // SAFETY: the caller's contract.
    unsafe { output_rows(out, m) }
}

/// Writes the `ROWS` rows of `COLUMNS` values one after the other.
///
/// # Safety
/// `out` points to room for `ROWS × COLUMNS` `f64`s.
unsafe fn output_rows<const COLUMNS: usize, const ROWS: usize>(
    out: *mut f64,
    m: [[f64; COLUMNS]; ROWS],
) {
    for (i, row) in m.into_iter().enumerate() {
        // SAFETY: row i goes to out[i COLUMNS .. (i + 1) COLUMNS], within the caller's room.
        unsafe { output(out.add(i * COLUMNS), row) }
    }
}

/// A robot's number of joints, its number of base parameters and its function lookup.
type Robot = (usize, usize, fn(&[u8]) -> Option<Function>);

/// The entry of `R`, its counts those of its trait impls.
fn entry<R: Timed<N, B>, const N: usize, const B: usize>(_: &R) -> Robot {
    (N, B, Functions::<R, N, B>::get)
}

/// The robot named `name` (`puma560`, `stanford`, `ur5`, `random5`, `panda`, `ur5_dh`,
/// `ur5_urdf`, the trees `baxter_no_mimic` and `allegro_right_hand`, or on a free-flying base
/// `solo12`, `anymal_b` and `g1_29dof`).
///
/// # Safety
/// `name` is null or a NUL-terminated string.
unsafe fn robot(name: *const c_char) -> Option<Robot> {
    if name.is_null() {
        return None;
    }
    // SAFETY: the caller's contract.
    Some(match unsafe { CStr::from_ptr(name) }.to_bytes() {
        b"puma560" => entry(&Puma560),
        b"stanford" => entry(&Stanford),
        b"ur5" => entry(&Ur5),
        b"random5" => entry(&Random5),
        b"panda" => entry(&Panda),
        b"ur5_dh" => entry(&Ur5Dh),
        b"ur5_urdf" => entry(&Ur5Urdf),
        b"baxter_no_mimic" => tree(&BaxterFreeFingers),
        b"allegro_right_hand" => tree(&AllegroHand),
        b"solo12" => floating_regressor::floating_with_regressor(&Solo12),
        b"anymal_b" => floating(&AnymalB),
        b"g1_29dof" => floating(&G1),
        _ => return None,
    })
}

/// The function `function` (`tau`, `M`, `g`, `C` or `h`, as in `timings`, or `fk`, `J`,
/// `JtF`, `fd`, `Minv`, `dtau`, `dqdd`, `Y`, `YB`, `piB`, or for `puma560` and `panda`
/// `tau_simplified`, `M_simplified`, `g_simplified`) of `robot`
/// (`puma560`, `stanford`, `ur5`, `random5`, `panda`, `ur5_dh` or `ur5_urdf`), or null for an unknown name.
///
/// # Safety
/// Both arguments are null or NUL-terminated strings.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_function(
    robot: *const c_char,
    function: *const c_char,
) -> Option<Function> {
    // SAFETY: the caller's contract.
    let (_, _, get) = unsafe { self::robot(robot) }?;
    if function.is_null() {
        return None;
    }
    // SAFETY: the caller's contract (both non-null: `self::robot` found one).
    let (robot, function) = unsafe { (CStr::from_ptr(robot), CStr::from_ptr(function)) };
    get(function.to_bytes()).or_else(|| simplified::get(robot.to_bytes(), function.to_bytes()))
}

/// The number of joints of `robot` (of a robot on a free-flying base, its `NV`: the joints and
/// the base's six), 0 for an unknown name, for the caller to check against its model.
///
/// # Safety
/// `robot` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_dof(robot: *const c_char) -> usize {
    // SAFETY: the caller's contract.
    unsafe { self::robot(robot) }.map_or(0, |(n, _, _)| n)
}

/// The number of base parameters of `robot` (the length of `piB`, the columns of `YB`), 0 for
/// an unknown name.
///
/// # Safety
/// `robot` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn dynamics_bench_base_count(robot: *const c_char) -> usize {
    // SAFETY: the caller's contract.
    unsafe { self::robot(robot) }.map_or(0, |(_, b, _)| b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dynamics_bench::{samples, Sample, ROBOTS};

    const FUNCTIONS: [&str; 15] = [
        "tau", "M", "g", "C", "h", "fk", "J", "JtF", "fd", "Minv", "dtau", "dqdd", "Y", "YB", "piB",
    ];
    /// Room for the largest output, `Y`'s 7 × 70 values.
    const ROOM: usize = 512;

    fn lookup(robot: &str, function: &str) -> Option<Function> {
        let robot = std::ffi::CString::new(robot).unwrap();
        let function = std::ffi::CString::new(function).unwrap();
        // SAFETY: two NUL-terminated strings.
        unsafe { dynamics_bench_function(robot.as_ptr(), function.as_ptr()) }
    }

    fn dof(robot: &str) -> usize {
        let robot = std::ffi::CString::new(robot).unwrap();
        // SAFETY: a NUL-terminated string.
        unsafe { dynamics_bench_dof(robot.as_ptr()) }
    }

    /// `function` of `robot` called through the C ABI on a sample, with room for [`ROOM`]
    /// outputs (NaN where nothing was written).
    fn call<const N: usize>(robot: &str, function: &str, s: &Sample<N>) -> [f64; ROOM] {
        let f = lookup(robot, function).expect("a known function");
        let mut out = [f64::NAN; ROOM];
        // SAFETY: N inputs each, room for 10 N × N ≤ ROOM outputs.
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

    fn direct<R: Timed<N, B>, const N: usize, const B: usize>(
        r: &R,
        function: &str,
        s: &Sample<N>,
    ) -> Vec<f64> {
        let rows = |m: [[f64; N]; N]| m.iter().flatten().copied().collect();
        match function {
            "tau" => r.inverse_dynamics(&s.q, &s.qd, &s.qdd).to_vec(),
            "M" => rows(r.mass_matrix(&s.q)),
            "g" => r.gravity_torques(&s.q).to_vec(),
            "C" => rows(r.coriolis_matrix(&s.q, &s.qd)),
            "h" => r.bias_torques(&s.q, &s.qd).to_vec(),
            "fk" => {
                let pose = r.hand_pose(&s.q);
                (0..3)
                    .flat_map(|i| [pose.rotation[i].as_slice(), &[pose.position[i]]].concat())
                    .collect()
            }
            "J" => r.hand_jacobian_in_base(&s.q).concat(),
            "JtF" => {
                let wrench = core::array::from_fn(|i| s.qdd[i]);
                r.joint_torques_for_base_wrench(&s.q, &wrench).to_vec()
            }
            // The third input as torques.
            "fd" => (r.forward_dynamics(&s.q, &s.qd, &s.qdd))
                .map_or(vec![f64::NAN; N], |qdd| qdd.to_vec()),
            "Minv" => r
                .mass_matrix_inverse(&s.q)
                .map_or(vec![f64::NAN; N * N], rows),
            "dtau" => {
                let d = r.inverse_dynamics_derivatives(&s.q, &s.qd, &s.qdd);
                [rows(d.dtau_dq), rows(d.dtau_dqd)].concat()
            }
            "dqdd" => r
                .forward_dynamics_derivatives(&s.q, &s.qd, &s.qdd)
                .map_or(vec![f64::NAN; 3 * N * N], |d| {
                    [rows(d.dqdd_dq), rows(d.dqdd_dqd), rows(d.dqdd_dtau)].concat()
                }),
            "Y" => {
                let y = r.regressor(&s.q, &s.qd, &s.qdd);
                y.iter().flatten().flatten().copied().collect()
            }
            "YB" => r.base_regressor(&s.q, &s.qd, &s.qdd).concat(),
            "piB" => r.base_parameters::<f64>().to_vec(),
            _ => unreachable!(),
        }
    }

    /// Every function of `robot` through the C ABI equals the trait method, writes nothing past
    /// its output, and its `tau` matches the reference data.
    fn check<R: Timed<N, B>, const N: usize, const B: usize>(r: &R, robot: &str) {
        assert_eq!(dof(robot), N, "{robot}");
        let robot_name = std::ffi::CString::new(robot).unwrap();
        // SAFETY: a NUL-terminated string.
        assert_eq!(unsafe { dynamics_bench_base_count(robot_name.as_ptr()) }, B);
        for s in samples::<N>(robot) {
            for function in FUNCTIONS {
                let want = direct(r, function, &s);
                let got = call(robot, function, &s);
                // Bit for bit, NaN (M not positive definite) included.
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                assert_eq!(bits(&got[..want.len()]), bits(&want), "{robot} {function}");
                assert!(
                    got[want.len()..].iter().all(|x| x.is_nan()),
                    "{robot} {function}"
                );
            }
            let err = dynamics_bench::scaled_error(&call(robot, "tau", &s)[..N], &s.tau);
            assert!(err < 1e-9, "{robot}: {err:e}");
        }
    }

    #[test]
    fn every_function_through_the_c_abi_equals_the_trait_method() {
        for robot in ROBOTS {
            match robot {
                "puma560" => check(&Puma560, robot),
                "stanford" => check(&Stanford, robot),
                "ur5" => check(&Ur5, robot),
                "random5" => check(&Random5, robot),
                "panda" => check(&Panda, robot),
                "ur5_dh" => check(&Ur5Dh, robot),
                "ur5_urdf" => check(&Ur5Urdf, robot),
                _ => panic!("{robot} has no test"),
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
        assert_eq!(dof("puma"), 0);
        // SAFETY: null is allowed.
        assert_eq!(unsafe { dynamics_bench_dof(core::ptr::null()) }, 0);
    }
}
