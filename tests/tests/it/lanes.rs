//! Every generated method on lane types against the single-state path, bit for bit
//! (`dynamics_tests::lanes`): `F64x4` on the reference robots, the URDF robots and their D-H
//! twins, a robot with friction (both signs of zero velocity, smoothed Coulomb friction) and
//! one with the regressor; `F32x8` against `f32`; `F64x2`, `F32x4` and `F64x8` on a few
//! robots. Each state set has a lane whose sines and cosines leave the fast range.
//! `forward_dynamics` with one lane whose mass matrix fails (a NaN): `Err` for the lanes, `Ok`
//! for the others one at a time.
//! And the reference data's samples four at a time against Pinocchio's τ, M and g directly.
//!
//! Run in the default build (SSE2, no FMA) and, by `.ci/run`, in a build for this CPU (AVX2
//! registers and fused multiply-adds).

use dynamics_reference::scaled_error;
use dynamics_runtime::lanes::{gather, F32x4, F32x8, F64x2, F64x4, F64x8, SplitLanes};
use dynamics_runtime::{Dynamics, NotPositiveDefinite};
use dynamics_tests::lanes::{derivatives, dynamics, regressor, Motion, States};
use dynamics_tests::reference::{flat, matrix, samples, vector, TOLERANCE};
use dynamics_tests::robots::urdf;
use dynamics_tests::robots::{
    General, NikuPolar, NikuTwoLink, Panda, PandaTwin, Puma560, Random1, Random2, Random5, Rubbing,
    Stanford, Tilted, Ur5, Ur5Twin, Ur5Urdf,
};

/// Every method in `F64x4`, and the derivatives where the robot has them.
macro_rules! f64x4 {
    ($($name:ident: $robot:expr, $n:literal $(, $family:ident)*;)*) => {$(
        #[test]
        fn $name() {
            let m = Motion::<F64x4, 4, $n>::new(0x1a7e5 + $n);
            dynamics(&$robot, &m);
            $($family(&$robot, &m);)*
        }
    )*};
}

f64x4! {
    puma560_f64x4: Puma560, 6, derivatives;
    stanford_f64x4: Stanford, 6, derivatives;
    ur5_f64x4: Ur5, 6;
    niku_2link_f64x4: NikuTwoLink, 2, derivatives;
    niku_polar_f64x4: NikuPolar, 2, derivatives;
    random1_f64x4: Random1, 2, derivatives;
    random2_f64x4: Random2, 3, derivatives;
    random5_f64x4: Random5, 6, derivatives;
    random5_regressor_f64x4: Random5, 6, regressor;
    panda_f64x4: Panda, 7, derivatives;
    ur5_frames_f64x4: Ur5Urdf, 6;
    tilted_f64x4: Tilted, 3;
    general_f64x4: General, 6;
    ur5_twin_f64x4: Ur5Twin, 6;
    panda_twin_f64x4: PandaTwin, 7;
    panda_urdf_f64x4: urdf::Panda, 7;
    friction_f64x4: Rubbing { fv2: 0.05, eps: 0.01 }, 2, derivatives;
}

#[test]
fn single_precision_f32x8() {
    dynamics(&Puma560, &Motion::<F32x8, 8, 6>::new(8));
    derivatives(&Puma560, &Motion::<F32x8, 8, 6>::new(9));
    derivatives(&Panda, &Motion::<F32x8, 8, 7>::new(10));
    regressor(&Random5, &Motion::<F32x8, 8, 6>::new(11));
    let rubbing = Rubbing {
        fv2: 0.05,
        eps: 0.01,
    };
    dynamics(&rubbing, &Motion::<F32x8, 8, 2>::new(12));
}

#[test]
fn two_and_four_lanes_f64x2_f32x4() {
    dynamics(&Puma560, &Motion::<F64x2, 2, 6>::new(13));
    dynamics(&Puma560, &Motion::<F32x4, 4, 6>::new(14));
    let rubbing = Rubbing {
        fv2: 0.05,
        eps: 0.01,
    };
    derivatives(&rubbing, &Motion::<F64x2, 2, 2>::new(15));
    derivatives(&rubbing, &Motion::<F32x4, 4, 2>::new(16));
}

/// Eight `f64` lanes: one AVX-512 register in a build for a CPU that has it. On a thread of its
/// own: the Panda's derivatives on 64-byte values outgrow a test thread's stack unoptimized.
#[test]
fn eight_lanes_f64x8() {
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(|| {
            dynamics(&Puma560, &Motion::<F64x8, 8, 6>::new(20));
            derivatives(&Panda, &Motion::<F64x8, 8, 7>::new(21));
            regressor(&Random5, &Motion::<F64x8, 8, 6>::new(22));
        })
        .expect("a thread")
        .join()
        .expect("every lane the scalar's");
}

/// A NaN in lane 2 fails that lane's pivot test: the lanes' `forward_dynamics` is `Err` (at
/// least one lane failed), the other states one at a time are `Ok`; the methods that do not
/// solve keep every other lane's value.
#[test]
fn one_failing_lane_makes_the_lanes_err() {
    let m = Motion::<F64x4, 4, 6>::new(17);
    let mut q = m.q.singles;
    q[2][1] = f64::NAN;
    let q = States::<F64x4, 4, 6>::new(q);
    let tau = [[1.0; 6]; 4];
    let lanes = Puma560.forward_dynamics(&q.lanes, &m.qd.lanes, &States::new(tau).lanes);
    assert_eq!(lanes, Err(NotPositiveDefinite));
    for (l, state) in q.singles.iter().enumerate() {
        let single = Puma560.forward_dynamics(state, &m.qd.singles[l], &tau[l]);
        assert_eq!(single.is_ok(), l != 2, "lane {l}");
    }
    assert!(Puma560.mass_matrix_inverse(&q.lanes).is_err());
    let lanes = Puma560
        .inverse_dynamics(&q.lanes, &m.qd.lanes, &m.qdd.lanes)
        .split_lanes();
    assert!(lanes[2].iter().any(|x| x.is_nan()));
    for l in [0, 1, 3] {
        let single = Puma560.inverse_dynamics(&q.singles[l], &m.qd.singles[l], &m.qdd.singles[l]);
        assert_eq!(
            lanes[l].map(f64::to_bits),
            single.map(f64::to_bits),
            "lane {l}"
        );
    }
}

/// The 20 samples of a reference data file, four at a time in `F64x4`: τ, M and g against
/// Pinocchio's to the reference tests' tolerance.
fn against_pinocchio<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) {
    let samples = samples(file);
    for (k, group) in samples.chunks_exact(4).enumerate() {
        let state = |key: &str| -> [F64x4; N] {
            gather(&core::array::from_fn(|l| vector::<N>(&group[l][key])))
        };
        let (q, qd, qdd) = (state("q"), state("qd"), state("qdd"));
        let tau = robot.inverse_dynamics(&q, &qd, &qdd).split_lanes();
        let m = robot.mass_matrix(&q).split_lanes();
        let g = robot.gravity_torques(&q).split_lanes();
        for (l, s) in group.iter().enumerate() {
            let errors = [
                scaled_error(&tau[l], &vector::<N>(&s["tau"])),
                scaled_error(&flat(m[l]), &flat(matrix::<N>(&s["M"]))),
                scaled_error(&g[l], &vector::<N>(&s["g"])),
            ];
            let worst = errors.iter().fold(0.0f64, |a, &b| a.max(b));
            assert!(
                worst < TOLERANCE,
                "{file}, sample {}: {errors:?}",
                4 * k + l
            );
        }
    }
}

#[test]
fn lanes_against_pinocchio_data() {
    against_pinocchio(&Puma560, "reference/data/puma560.json");
    against_pinocchio(&Stanford, "reference/data/stanford.json");
    against_pinocchio(&Random5, "reference/data/random5.json");
    against_pinocchio(&Panda, "panda/data.json");
}
