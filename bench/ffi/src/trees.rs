//! The trees' entries ([`tree`]): the dynamics and their derivatives of a robot that branches,
//! which has no hand frame, regressor or base parameters in the benchmark.

use super::{Functions, Robot};
use dynamics_runtime::DynamicsDerivatives;

/// The entry of the tree `R`: its dynamics and their derivatives alone, no base parameters.
pub(super) fn tree<R: DynamicsDerivatives<N> + Default, const N: usize>(_: &R) -> Robot {
    (N, 0, Functions::<R, N, 0>::dynamics)
}

#[cfg(test)]
mod tests {
    use crate::{dynamics_bench_dof, dynamics_bench_function, Function};
    use dynamics_bench::{samples, AllegroHand, BaxterFreeFingers};
    use dynamics_runtime::DynamicsDerivatives;

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

    /// A tree's functions through the C ABI, each the trait method's bits, writing nothing past
    /// its output, `tau` the data's; it has no hand frame, regressor or base parameters.
    fn check_tree<R: DynamicsDerivatives<N>, const N: usize>(r: &R, robot: &str) {
        assert_eq!(dof(robot), N, "{robot}");
        let rows = |m: [[f64; N]; N]| m.iter().flatten().copied().collect::<Vec<f64>>();
        for s in samples::<N>(robot) {
            let d = r.inverse_dynamics_derivatives(&s.q, &s.qd, &s.qdd);
            let fd = r
                .forward_dynamics_derivatives(&s.q, &s.qd, &s.tau)
                .expect("M > 0");
            let tau = r.inverse_dynamics(&s.q, &s.qd, &s.qdd).to_vec();
            let checks = [
                ("tau", s.qdd, tau.clone()),
                ("M", s.qdd, rows(r.mass_matrix(&s.q))),
                ("g", s.qdd, r.gravity_torques(&s.q).to_vec()),
                ("C", s.qdd, rows(r.coriolis_matrix(&s.q, &s.qd))),
                ("h", s.qdd, r.bias_torques(&s.q, &s.qd).to_vec()),
                (
                    "fd",
                    s.tau,
                    r.forward_dynamics(&s.q, &s.qd, &s.tau)
                        .expect("M > 0")
                        .to_vec(),
                ),
                (
                    "Minv",
                    s.qdd,
                    rows(r.mass_matrix_inverse(&s.q).expect("M > 0")),
                ),
                ("dtau", s.qdd, [rows(d.dtau_dq), rows(d.dtau_dqd)].concat()),
                (
                    "dqdd",
                    s.tau,
                    [rows(fd.dqdd_dq), rows(fd.dqdd_dqd), rows(fd.dqdd_dtau)].concat(),
                ),
            ];
            for (function, third, want) in checks {
                let f = lookup(robot, function).expect("a tree's function");
                let mut got = vec![f64::NAN; 3 * N * N + 1];
                if function == "M" {
                    // Its contract: zeros where M is zero at every state.
                    got[..N * N].fill(0.0);
                }
                // SAFETY: N inputs each, room for the largest output (3 N × N) and one more.
                unsafe {
                    f(
                        s.q.as_ptr(),
                        s.qd.as_ptr(),
                        third.as_ptr(),
                        got.as_mut_ptr(),
                    )
                };
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                assert_eq!(bits(&got[..want.len()]), bits(&want), "{robot} {function}");
                assert!(
                    got[want.len()..].iter().all(|x| x.is_nan()),
                    "{robot} {function}"
                );
            }
            let err = dynamics_bench::scaled_error(&tau, &s.tau);
            assert!(err < 1e-9, "{robot}: {err:e}");
        }
        for function in ["fk", "J", "JtF", "Y", "YB", "piB", "tau_batch"] {
            assert!(lookup(robot, function).is_none(), "{robot} {function}");
        }
    }

    /// A tree's `M` through the C ABI writes the elements along its branches and leaves the
    /// blocks between them as the caller's matrix has them: a matrix kept across the samples,
    /// zeroed once, holds each sample's M bit for bit, and a marker put between the branches
    /// stays there (only where M is zero at the sample).
    fn check_mass_kept<R: DynamicsDerivatives<N>, const N: usize>(r: &R, robot: &str) {
        let f = lookup(robot, "M").expect("a tree's M");
        let call = |q: &[f64; N], out: &mut [f64]| {
            // SAFETY: N joint values, room for N × N outputs; the other inputs are not read.
            unsafe { f(q.as_ptr(), q.as_ptr(), q.as_ptr(), out.as_mut_ptr()) }
        };
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        let mut kept = vec![0.0; N * N];
        for s in samples::<N>(robot) {
            let want: Vec<f64> = r.mass_matrix(&s.q).iter().flatten().copied().collect();
            call(&s.q, &mut kept);
            assert_eq!(bits(&kept), bits(&want), "{robot}: M into a kept matrix");
            let marker = 7.5;
            let mut marked = vec![marker; N * N];
            call(&s.q, &mut marked);
            let left = (0..N * N).filter(|&k| marked[k] == marker).count();
            assert!(
                left >= 2 * 3 * 4,
                "{robot}: {left} markers left between the branches"
            );
            for (k, (&got, &want)) in marked.iter().zip(&want).enumerate() {
                if got == marker {
                    assert_eq!(want, 0.0, "{robot}: M[{k}] left unwritten");
                } else {
                    assert_eq!(got.to_bits(), want.to_bits(), "{robot}: M[{k}]");
                }
            }
        }
    }

    #[test]
    fn a_tree_s_mass_matrix_leaves_the_callers_zeros_between_branches() {
        check_mass_kept(&BaxterFreeFingers, "baxter_no_mimic");
        check_mass_kept(&AllegroHand, "allegro_right_hand");
    }

    #[test]
    fn a_tree_s_dynamics_through_the_c_abi_equal_the_trait_methods() {
        check_tree(&BaxterFreeFingers, "baxter_no_mimic");
        check_tree(&AllegroHand, "allegro_right_hand");
    }
}
