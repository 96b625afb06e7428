//! The `_batch` methods against one call per state, bit for bit: every length from 0 to past
//! two groups (the partial last group), both layouts of inputs and outputs, `f64` and `f32`,
//! the solves with failing states among good ones, the wrench's six values, the regressors.

use dynamics_runtime::batch::{States, StatesMut};
use dynamics_runtime::F64x4;
use dynamics_runtime::{
    DerivativesBatchScalar, Dynamics, DynamicsBaseParametersBatch, DynamicsBatch,
    DynamicsDerivatives, DynamicsDerivativesBatch, DynamicsRegressorBatch, NotPositiveDefinite,
    Real,
};
use dynamics_tests::lanes::{close_values, routes_differ, Bits};
use dynamics_tests::robots::{Panda, Puma560, Stanford};

/// Lengths around the groups of four (`f64`) and eight (`f32`, the derivatives' `f64` with
/// AVX-512).
const LENGTHS: [usize; 8] = [0, 1, 3, 4, 5, 8, 9, 19];

/// `count` states of `N` values in `[-2, 2)`, deterministic.
fn states<const N: usize>(count: usize, seed: u64) -> Vec<[f64; N]> {
    let mut x = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1_u64 << 53) as f64 * 4.0 - 2.0
    };
    (0..count)
        .map(|_| core::array::from_fn(|_| next()))
        .collect()
}

fn bits<X: Bits>(x: &X) -> Vec<u64> {
    let mut out = Vec::new();
    x.bits(&mut out);
    out
}

/// Each result equals `single` of its state, bit for bit.
fn same<O: Bits>(what: &str, batch: &[O], single: impl Fn(usize) -> O) {
    for (k, value) in batch.iter().enumerate() {
        assert_eq!(
            bits(value),
            bits(&single(k)),
            "{what}, state {k} of {}",
            batch.len()
        );
    }
}

/// A solve's results: `Err` exactly where the state's own is.
fn same_solved<O: Bits>(
    what: &str,
    batch: &[Result<O, NotPositiveDefinite>],
    single: impl Fn(usize) -> Result<O, NotPositiveDefinite>,
) {
    for (k, value) in batch.iter().enumerate() {
        match (value, single(k)) {
            (Ok(a), Ok(b)) => assert_eq!(bits(a), bits(&b), "{what}, state {k}"),
            (Err(_), Err(_)) => {}
            (a, b) => panic!("{what}, state {k}: {:?} against {:?}", a.is_ok(), b.is_ok()),
        }
    }
}

/// Runs `f` on a thread, and rayon's work on a pool, with room for the derivatives' batches:
/// on `F64x8` (AVX-512) the Panda's derivatives take about 4 MB of stack unoptimized, more than
/// a thread's 2 MB (as `lanes.rs`' `eight_lanes_f64x8`).
fn with_room(f: impl FnOnce() + Send) {
    let pool = rayon::ThreadPoolBuilder::new()
        .stack_size(64 << 20)
        .build()
        .expect("a pool");
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(64 << 20)
            .spawn_scoped(s, || pool.install(f))
            .expect("a thread");
    });
}

fn dynamics_methods<R: DynamicsDerivatives<N>, const N: usize>(robot: &R, name: &str) {
    for len in LENGTHS {
        let (q, qd, qdd) = (
            states::<N>(len, 1),
            states::<N>(len, 2),
            states::<N>(len, 3),
        );
        let mut tau = vec![[0.0; N]; len];
        robot.inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
        same(name, &tau, |k| {
            robot.inverse_dynamics(&q[k], &qd[k], &qdd[k])
        });
        let mut m = vec![[[0.0; N]; N]; len];
        robot.mass_matrix_batch(&q[..], &mut m[..]);
        same(name, &m, |k| robot.mass_matrix(&q[k]));
        let mut energy = vec![0.0; len];
        robot.kinetic_energy_batch(&q[..], &qd[..], &mut energy[..]);
        same(name, &energy, |k| robot.kinetic_energy(&q[k], &qd[k]));
        let mut pose = vec![robot.hand_pose(&[0.0; N]); len];
        robot.hand_pose_batch(&q[..], &mut pose[..]);
        same(name, &pose, |k| robot.hand_pose(&q[k]));
        let wrench = states::<6>(len, 4);
        let mut statics = vec![[0.0; N]; len];
        robot.joint_torques_for_base_wrench_batch(&q[..], &wrench[..], &mut statics[..]);
        same(name, &statics, |k| {
            robot.joint_torques_for_base_wrench(&q[k], &wrench[k])
        });
        let mut d = vec![robot.inverse_dynamics_derivatives(&[0.0; N], &[0.0; N], &[0.0; N]); len];
        robot.inverse_dynamics_derivatives_batch(&q[..], &qd[..], &qdd[..], &mut d[..]);
        if routes_differ::<F64x4, 4>() {
            for (k, d) in d.iter().enumerate() {
                let single = robot.inverse_dynamics_derivatives(&q[k], &qd[k], &qdd[k]);
                close_values(&format!("{name}, state {k}"), d, &single, 1e-12);
            }
        } else {
            same(name, &d, |k| {
                robot.inverse_dynamics_derivatives(&q[k], &qd[k], &qdd[k])
            });
        }
    }
}

#[test]
fn every_length_as_one_call_per_state() {
    with_room(|| {
        dynamics_methods(&Puma560, "puma560");
        dynamics_methods(&Stanford, "stanford");
        dynamics_methods(&Panda, "panda");
    });
}

/// The derivatives' batches take eight `f64` states a group where the build computes tangents
/// in lanes (AVX-512), four otherwise; `f32` eight either way.
#[test]
fn derivatives_in_groups_of_eight_where_tangents_are_in_lanes() {
    fn group<T: DerivativesBatchScalar<L>, const L: usize>(_: T) -> usize {
        L
    }
    let f64_group = if <f64 as Real>::TANGENTS_IN_LANES {
        8
    } else {
        4
    };
    assert_eq!(group(0.0_f64), f64_group);
    assert_eq!(group(0.0_f32), 8);
}

#[test]
fn solves_fail_exactly_for_the_failing_states() {
    with_room(solves_fail);
}

fn solves_fail() {
    let len = 11;
    let (mut q, qd, tau) = (
        states::<7>(len, 5),
        states::<7>(len, 6),
        states::<7>(len, 7),
    );
    // A NaN pivot is not positive: states 2 and 9, in the first and the last group (M does
    // not depend on q1).
    q[2][3] = f64::NAN;
    q[9][4] = f64::NAN;
    let mut qdd = vec![Ok([0.0; 7]); len];
    Panda.forward_dynamics_batch(&q[..], &qd[..], &tau[..], &mut qdd[..]);
    same_solved("forward_dynamics", &qdd, |k| {
        Panda.forward_dynamics(&q[k], &qd[k], &tau[k])
    });
    assert_eq!(qdd.iter().filter(|r| r.is_err()).count(), 2);
    let mut inverse = vec![Ok([[0.0; 7]; 7]); len];
    Panda.mass_matrix_inverse_batch(&q[..], &mut inverse[..]);
    same_solved("mass_matrix_inverse", &inverse, |k| {
        Panda.mass_matrix_inverse(&q[k])
    });
    let mut d = vec![Panda.forward_dynamics_derivatives(&q[0], &qd[0], &tau[0]); len];
    Panda.forward_dynamics_derivatives_batch(&q[..], &qd[..], &tau[..], &mut d[..]);
    let single = |k: usize| Panda.forward_dynamics_derivatives(&q[k], &qd[k], &tau[k]);
    if routes_differ::<F64x4, 4>() {
        // The states in lanes solve column by column, one state on its tangents' lanes.
        for (k, d) in d.iter().enumerate() {
            match (d, single(k)) {
                (Ok(a), Ok(b)) => close_values(&format!("state {k}"), a, &b, 1e-9),
                (Err(_), Err(_)) => {}
                (a, b) => panic!("state {k}: {:?} against {:?}", a.is_ok(), b.is_ok()),
            }
        }
    } else {
        same_solved("forward_dynamics_derivatives", &d, single);
    }
}

/// One slice per joint.
fn slices(columns: &[Vec<f64>]) -> [&[f64]; 6] {
    core::array::from_fn(|j| columns[j].as_slice())
}

#[test]
fn joint_columns_in_and_out() {
    let len = 13;
    let (q, qd, qdd) = (
        states::<6>(len, 8),
        states::<6>(len, 9),
        states::<6>(len, 10),
    );
    // The same states, one slice per joint.
    let column = |s: &[[f64; 6]], j: usize| s.iter().map(|x| x[j]).collect::<Vec<f64>>();
    let [qc, qdc, qddc] = [&q, &qd, &qdd].map(|s| (0..6).map(|j| column(s, j)).collect::<Vec<_>>());
    let (qs, qds, qdds) = (slices(&qc), slices(&qdc), slices(&qddc));
    assert_eq!(States::<f64, 6>::count(&qs), len);
    let mut columns = vec![vec![0.0; len]; 6];
    {
        let mut out: [&mut [f64]; 6] = {
            let mut it = columns.iter_mut();
            core::array::from_fn(|_| it.next().unwrap().as_mut_slice())
        };
        assert_eq!(StatesMut::<[f64; 6]>::count(&out), len);
        Puma560.inverse_dynamics_batch(&qs, &qds, &qdds, &mut out);
    }
    let mut tau = vec![[0.0; 6]; len];
    Puma560.inverse_dynamics_batch(&qs, &qd[..], &qdds, &mut tau[..]);
    same("joint columns in", &tau, |k| {
        Puma560.inverse_dynamics(&q[k], &qd[k], &qdd[k])
    });
    for (k, t) in tau.iter().enumerate() {
        for j in 0..6 {
            assert_eq!(
                columns[j][k].to_bits(),
                t[j].to_bits(),
                "joint {j}, state {k}"
            );
        }
    }
}

#[test]
fn single_precision_in_groups_of_eight() {
    for len in LENGTHS {
        let narrow = |s: Vec<[f64; 7]>| -> Vec<[f32; 7]> {
            s.into_iter().map(|x| x.map(|v| v as f32)).collect()
        };
        let q = narrow(states::<7>(len, 11));
        let qd = narrow(states::<7>(len, 12));
        let qdd = narrow(states::<7>(len, 13));
        let mut tau = vec![[0.0_f32; 7]; len];
        Panda.inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
        same("panda f32", &tau, |k| {
            Panda.inverse_dynamics(&q[k], &qd[k], &qdd[k])
        });
        let mut m = vec![[[0.0_f32; 7]; 7]; len];
        Panda.mass_matrix_batch(&q[..], &mut m[..]);
        same("panda f32", &m, |k| Panda.mass_matrix(&q[k]));
    }
}

#[test]
fn regressors_in_batches() {
    let robot = Puma560;
    let len = 6;
    let (q, qd, qdd) = (
        states::<6>(len, 14),
        states::<6>(len, 15),
        states::<6>(len, 16),
    );
    let mut y = vec![[[[0.0; 10]; 6]; 6]; len];
    robot.regressor_batch(&q[..], &qd[..], &qdd[..], &mut y[..]);
    same("regressor", &y, |k| {
        dynamics_runtime::DynamicsRegressor::regressor(&robot, &q[k], &qd[k], &qdd[k])
    });
    let mut yb = vec![[[0.0; 36]; 6]; len];
    robot.base_regressor_batch(&q[..], &qd[..], &qdd[..], &mut yb[..]);
    same("base_regressor", &yb, |k| {
        dynamics_runtime::DynamicsBaseParameters::base_regressor(&robot, &q[k], &qd[k], &qdd[k])
    });
}

#[test]
#[should_panic(expected = "`qd` holds 3 states, the output 4")]
fn inputs_of_another_length_panic() {
    let (q, qd) = (states::<6>(4, 1), states::<6>(3, 2));
    let mut tau = [[0.0; 6]; 4];
    Puma560.coriolis_torques_batch(&q[..], &qd[..], &mut tau[..]);
}

/// Large enough to be cut into chunks on the threads (a partial last group too), below the
/// threshold where it runs on the caller's thread, and through joint columns.
#[test]
fn threads_give_the_same_bits() {
    with_room(threads_agree);
}

fn threads_agree() {
    use dynamics_runtime::InParallel;
    for len in [0, 5, 1_003, 4_100, 9_001] {
        let (q, qd, qdd) = (
            states::<7>(len, 17),
            states::<7>(len, 18),
            states::<7>(len, 19),
        );
        let mut tau = vec![[0.0; 7]; len];
        InParallel(&Panda).inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
        same("parallel τ", &tau, |k| {
            Panda.inverse_dynamics(&q[k], &qd[k], &qdd[k])
        });
        // Against one thread's batch: in AVX-512 builds the single state's derivatives take
        // another route (tangents in lanes), the lanes' agree with it to rounding only.
        let zero = Panda.inverse_dynamics_derivatives(&[0.0; 7], &[0.0; 7], &[0.0; 7]);
        let (mut d, mut one_thread) = (vec![zero; len], vec![zero; len]);
        InParallel(&Panda).inverse_dynamics_derivatives_batch(
            &q[..],
            &qd[..],
            &qdd[..],
            &mut d[..],
        );
        Panda.inverse_dynamics_derivatives_batch(&q[..], &qd[..], &qdd[..], &mut one_thread[..]);
        same("parallel ∂τ", &d, |k| one_thread[k]);
        let mut solved = vec![Ok([0.0; 7]); len];
        InParallel(&Panda).forward_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut solved[..]);
        same_solved("parallel q̈", &solved, |k| {
            Panda.forward_dynamics(&q[k], &qd[k], &qdd[k])
        });
        let mut columns = vec![vec![0.0; len]; 7];
        let mut out: [&mut [f64]; 7] = {
            let mut it = columns.iter_mut();
            core::array::from_fn(|_| it.next().unwrap().as_mut_slice())
        };
        InParallel(&Panda).gravity_torques_batch(&q[..], &mut out);
        for (k, state) in q.iter().enumerate() {
            let g = Panda.gravity_torques(state);
            for j in 0..7 {
                assert_eq!(
                    columns[j][k].to_bits(),
                    g[j].to_bits(),
                    "joint {j}, state {k}"
                );
            }
        }
    }
}

/// States with one NaN or ±∞ among finite values, at every joint of q, q̇ and q̈, in every lane
/// of a group: each result is its own call's, a NaN where it has a NaN (of a sign the compiler
/// chooses: in an optimized SSE2 build, PUMA 560's τ with a NaN q̇₂ had −NaN in one and +NaN in
/// the other).
#[test]
fn non_finite_states_as_their_own_calls() {
    const N: usize = 6;
    let mut q = Vec::new();
    let (mut qd, mut qdd) = (Vec::new(), Vec::new());
    let finite = states::<N>(3 * N * 3, 21);
    for (i, x) in [f64::NAN, -f64::NAN, f64::INFINITY, f64::NEG_INFINITY]
        .into_iter()
        .enumerate()
    {
        for slot in 0..3 * N {
            let mut s = [finite[slot], finite[slot + 1], finite[slot + 2]];
            s[slot / N][slot % N] = x;
            // The special state at lane `slot % 4`, finite states around it.
            for k in 0..4 {
                let s = if k == (slot + i) % 4 {
                    s
                } else {
                    [finite[k], finite[k + 3], finite[k + 6]]
                };
                q.push(s[0]);
                qd.push(s[1]);
                qdd.push(s[2]);
            }
        }
    }
    let len = q.len();
    let mut tau = vec![[0.0; N]; len];
    Puma560.inverse_dynamics_batch(&q[..], &qd[..], &qdd[..], &mut tau[..]);
    same("τ", &tau, |k| {
        Puma560.inverse_dynamics(&q[k], &qd[k], &qdd[k])
    });
    let mut m = vec![[[0.0; N]; N]; len];
    Puma560.mass_matrix_batch(&q[..], &mut m[..]);
    same("M", &m, |k| Puma560.mass_matrix(&q[k]));
    let mut c = vec![[0.0; N]; len];
    Puma560.coriolis_torques_batch(&q[..], &qd[..], &mut c[..]);
    same("C q̇", &c, |k| Puma560.coriolis_torques(&q[k], &qd[k]));
    let mut g = vec![[0.0; N]; len];
    Puma560.gravity_torques_batch(&q[..], &mut g[..]);
    same("g", &g, |k| Puma560.gravity_torques(&q[k]));
    let mut energy = vec![0.0; len];
    Puma560.kinetic_energy_batch(&q[..], &qd[..], &mut energy[..]);
    same("kinetic energy", &energy, |k| {
        Puma560.kinetic_energy(&q[k], &qd[k])
    });
    let mut pose = vec![Puma560.hand_pose(&[0.0; N]); len];
    Puma560.hand_pose_batch(&q[..], &mut pose[..]);
    same("pose", &pose, |k| Puma560.hand_pose(&q[k]));
}

/// One slice per joint, one of them shorter than the first: the batch refuses before it reads,
/// naming the slice and the lengths, as it does an input of another length.
#[test]
#[should_panic(
    expected = "`qd` has slices of different lengths: its first holds 5 states, its slice 3 holds 4"
)]
fn ragged_joint_slices_in_panic_with_their_lengths() {
    let long = [0.1; 5];
    let short = [0.2; 4];
    let q: [&[f64]; 6] = [&long; 6];
    let qd: [&[f64]; 6] = [&long, &long, &long, &short, &long, &long];
    let mut tau = [[0.0; 6]; 5];
    Puma560.coriolis_torques_batch(&q, &qd, &mut tau[..]);
}

#[test]
#[should_panic(
    expected = "the output has slices of different lengths: its first holds 5 results, its slice 2 holds 6"
)]
fn ragged_joint_slices_out_panic_with_their_lengths() {
    let q = states::<6>(5, 1);
    let mut columns = [
        vec![0.0; 5],
        vec![0.0; 5],
        vec![0.0; 6],
        vec![0.0; 5],
        vec![0.0; 5],
        vec![0.0; 5],
    ];
    let mut out: [&mut [f64]; 6] = {
        let mut it = columns.iter_mut();
        core::array::from_fn(|_| it.next().unwrap().as_mut_slice())
    };
    Puma560.gravity_torques_batch(&q[..], &mut out);
}
