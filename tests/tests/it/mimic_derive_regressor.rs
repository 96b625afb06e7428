//! The generated regressor and base parameters of robots with mimic joints: `N` rows (the
//! coordinates) and `LINKS` column blocks (one per joint, the mimic ones' kept), through the
//! traits `DynamicsRegressor<N, LINKS>` and `DynamicsBaseParameters<N, B, LINKS>`.
//!
//! * An arm in the attribute whose third joint follows the second (`q₃ = −0.7 q₂ + 0.3`, with
//!   friction and actuator inertia of its own): `Y π` plus the joint columns in their rows
//!   (`JOINT_ROWS`) is `inverse_dynamics`, `Y_B π_B` too, and `Y` is `Sᵀ Y_free` of the same arm
//!   derived with every joint free at `q_full = S q + o` (S written by hand, 4 × 3).
//! * The Panda of `robots/urdf/panda.urdf` (its second finger mimics the first: 8 coordinates, 9
//!   links) against Pinocchio 4.1 (`tests/data/trees/panda_fingers_regressor.json`, by
//!   `mimic_regressor.py`): Y entry by entry, `Y π = τ`, and 48 base parameters, the rank of
//!   Pinocchio's projected regressor (`mimic_regressor.rs` computes it from the file).
//! * The batch form over states of the mimic arm.

use crate::mimic_regressor::rank;
use dynamics_reference::scaled_error;
use dynamics_runtime::{Dynamics, DynamicsBaseParameters, DynamicsRegressor};
use dynamics_tests::reference::TOLERANCE;
use serde_json::Value;

macro_rules! arm {
    ($name:ident $(, $($mimic:tt)*)?) => {
        #[derive(Dynamics)]
        #[dynamics(
            gravity = [0.3, -0.2, -9.81],
            regressor = true,
            base_parameters = true,
            joints = [
                revolute(xyz = [0, 0, 0.3], rpy = [0, 0, 0.2]),
                revolute(name = "shoulder", xyz = [0.1, 0, 0.2], rpy = [90 deg, 0, 0]),
                revolute(xyz = [0.4, 0.05, 0], rpy = [0.1, 0.2, 0.3], axis = [0, 0.6, 0.8] $(, $($mimic)*)?),
                revolute(xyz = [0.3, 0, 0.02], rpy = [-90 deg, 0, 0], axis = [1, 0, 0]),
            ],
            link(mass = 2.0, com = [0, 0.01, -0.1], inertia = [0.05, 0.05, 0.02, 0, 0, 0.001]),
            link(mass = 1.5, com = [0.15, 0, 0.01], inertia = [0.01, 0.04, 0.04, 0.001, 0, 0],
                 friction = (viscous = 0.2)),
            link(mass = 1.1, com = [0.1, 0.02, 0], inertia = [0.008, 0.02, 0.02, 0, 0.001, 0],
                 actuator_inertia = 0.03,
                 friction = (viscous = 0.5, coulomb = 0.3, smoothing = 0.4)),
            link(mass = 0.6, com = [0.05, 0, 0.02], inertia = [0.002, 0.003, 0.003, 0, 0, 0]),
        )]
        struct $name;
    };
}

arm!(Free);
arm!(
    Mimic,
    mimic = (joint = "shoulder", multiplier = -0.7, offset = 0.3)
);

const K: f64 = -0.7;
const O: f64 = 0.3;

/// The four joints' values of the coordinates' `x` (`with_offset` for positions).
fn full(x: &[f64; 3], with_offset: bool) -> [f64; 4] {
    let o = if with_offset { O } else { 0.0 };
    [x[0], x[1], K * x[1] + o, x[2]]
}

/// `Y π` plus each joint's columns times its parameters in its row: `inverse_dynamics` of a
/// robot without springs.
fn predicted<R, const N: usize, const L: usize>(
    robot: &R,
    q: &[f64; N],
    qd: &[f64; N],
    qdd: &[f64; N],
) -> [f64; N]
where
    R: DynamicsRegressor<N, L>,
{
    let (y, pi) = (
        robot.regressor(q, qd, qdd),
        robot.standard_parameters::<f64>(),
    );
    let (yj, pj) = (
        robot.joint_regressor(qd, qdd),
        robot.joint_parameters::<f64>(),
    );
    let mut tau: [f64; N] = std::array::from_fn(|i| {
        (0..L)
            .map(|j| (0..10).map(|k| y[i][j][k] * pi[j][k]).sum::<f64>())
            .sum()
    });
    for (m, &row) in R::JOINT_ROWS.iter().enumerate() {
        tau[row] += (0..4).map(|k| yj[m][k] * pj[m][k]).sum::<f64>();
    }
    tau
}

fn check(what: &str, got: &[f64], want: &[f64]) {
    let e = scaled_error(got, want);
    assert!(
        e < TOLERANCE,
        "{what} off by {e:e}\n got {got:?}\nwant {want:?}"
    );
}

#[test]
fn a_mimic_arms_regressor_has_a_block_per_link_and_a_row_per_coordinate() {
    assert_eq!(<Mimic as DynamicsRegressor<3, 4>>::LINK_COUNT, 4);
    assert_eq!(<Mimic as DynamicsRegressor<3, 4>>::JOINT_ROWS, [0, 1, 1, 2]);
    assert_eq!(<Free as DynamicsRegressor<4>>::JOINT_ROWS, [0, 1, 2, 3]);
    let states = [
        ([0.4, -0.9, 1.3], [0.7, -1.1, 0.4], [1.2, 0.3, -0.8]),
        ([-2.1, 0.5, 0.05], [-0.2, 1.6, -1.3], [-0.4, 2.0, 0.9]),
        ([1.0, 2.5, -0.6], [0.0, 0.3, 2.2], [0.5, -1.5, 0.1]),
    ];
    for (q, qd, qdd) in states {
        let tau = Mimic.inverse_dynamics(&q, &qd, &qdd);
        check("Y π + joints", &predicted(&Mimic, &q, &qd, &qdd), &tau);
        check(
            "Y_B π_B",
            &crate::base_parameters::predicted(&Mimic, &q, &qd, &qdd),
            &tau,
        );
        // Y = Sᵀ Y_free at the full state: rows 1 and 2 of the free arm's summed, 2 times K.
        let (fq, fqd, fqdd) = (full(&q, true), full(&qd, false), full(&qdd, false));
        let y_free = Free.regressor(&fq, &fqd, &fqdd);
        let projected: Vec<f64> = [0, 1, 3]
            .iter()
            .map(|&r| match r {
                1 => std::array::from_fn::<_, 4, _>(|j| {
                    std::array::from_fn::<_, 10, _>(|k| y_free[1][j][k] + K * y_free[2][j][k])
                }),
                _ => y_free[r],
            })
            .flat_map(|row| row.into_iter().flatten())
            .collect();
        let y = Mimic.regressor(&q, &qd, &qdd);
        let y: Vec<f64> = y.iter().flatten().flatten().copied().collect();
        check("Y = Sᵀ Y_free", &y, &projected);
    }
}

#[test]
fn a_mimic_arms_base_parameters_map_from_its_standard_ones() {
    let (pi, pj) = (
        Mimic.standard_parameters::<f64>(),
        Mimic.joint_parameters::<f64>(),
    );
    let (p, p_j) = (
        Mimic.base_from_standard::<f64>(),
        Mimic.base_from_joints::<f64>(),
    );
    let base = Mimic.base_parameters::<f64>();
    let mapped: Vec<f64> = (0..base.len())
        .map(|b| {
            let links: f64 = (0..4)
                .map(|j| (0..10).map(|k| p[b][j][k] * pi[j][k]).sum::<f64>())
                .sum();
            let joints: f64 = (0..4)
                .map(|i| (0..4).map(|k| p_j[b][i][k] * pj[i][k]).sum::<f64>())
                .sum();
            links + joints
        })
        .collect();
    check("P π + P_J p", &mapped, &base);
    // The coupling makes fewer combinations identifiable than the free arm's.
    assert!(base.len() < Free.base_parameters::<f64>().len());
}

#[test]
fn a_mimic_arms_regressor_in_batches() {
    use dynamics_runtime::DynamicsRegressorBatch;
    let (q, qd, qdd) = ([0.4, -0.9, 1.3], [0.7, -1.1, 0.4], [1.2, 0.3, -0.8]);
    let states = [q, [0.1, 0.2, 0.3]];
    let (rates, accelerations) = ([qd, qd], [qdd, qdd]);
    let mut out = [[[[0.0; 10]; 4]; 3]; 2];
    Mimic.regressor_batch(&states[..], &rates[..], &accelerations[..], &mut out[..]);
    let y = Mimic.regressor(&q, &qd, &qdd);
    let flat =
        |y: &[[[f64; 10]; 4]; 3]| -> Vec<f64> { y.iter().flatten().flatten().copied().collect() };
    check("batch", &flat(&out[0]), &flat(&y));
}

#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/panda.urdf",
    base = "panda_link0",
    regressor = true,
    base_parameters = true
)]
struct PandaMimic;

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        x => vec![x.as_f64().expect("a number")],
    }
}

fn eight(v: &Value) -> [f64; 8] {
    numbers(v).try_into().expect("eight numbers")
}

#[test]
fn the_generated_regressor_of_the_mimic_panda_is_pinocchios() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/trees/panda_fingers_regressor.json"
    );
    let file: Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("readable")).expect("JSON");
    let pi: Vec<f64> = PandaMimic
        .standard_parameters::<f64>()
        .iter()
        .flatten()
        .copied()
        .collect();
    let mut worst = scaled_error(&pi, &numbers(&file["pi"]));
    for sample in file["samples"].as_array().expect("samples") {
        let [q, qd, qdd] = ["q", "qd", "qdd"].map(|k| eight(&sample[k]));
        let y = PandaMimic.regressor(&q, &qd, &qdd);
        let y: Vec<f64> = y.iter().flatten().flatten().copied().collect();
        // Y π, the rigid bodies' τ, is Pinocchio's; with the joints' terms (the URDF's damping
        // and friction), `inverse_dynamics`.
        let y_pi: Vec<f64> = y
            .chunks(pi.len())
            .map(|row| row.iter().zip(&pi).map(|(a, b)| a * b).sum())
            .collect();
        let tau = PandaMimic.inverse_dynamics(&q, &qd, &qdd);
        worst = worst
            .max(scaled_error(&y, &numbers(&sample["Y"])))
            .max(scaled_error(&y_pi, &numbers(&sample["tau"])))
            .max(scaled_error(&predicted(&PandaMimic, &q, &qd, &qdd), &tau))
            .max(scaled_error(
                &crate::base_parameters::predicted(&PandaMimic, &q, &qd, &qdd),
                &tau,
            ));
    }
    println!("the derived mimic Panda's regressor against Pinocchio: {worst:.1e}");
    assert!(worst < TOLERANCE, "{worst:e}");
    // The links' parameters group into 48 (the rank of Pinocchio's projected regressor over the
    // file's samples, `mimic_regressor.rs`); the URDF's damping and friction add their own.
    let (links, base) = ranks_over_states();
    assert_eq!(links, 48);
    assert_eq!(base, PandaMimic.base_parameters::<f64>().len());
}

/// Over random states, the numerical rank of the links' columns, and of `Y_B` beside them: `B`
/// when `Y_B` has full column rank and spans every link column.
fn ranks_over_states() -> (usize, usize) {
    let mut seed = 41_u64;
    let mut next = || {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        #[allow(clippy::cast_precision_loss)]
        let x = (seed >> 11) as f64 / (1_u64 << 53) as f64;
        4.0 * x - 2.0
    };
    let (mut links, mut both) = (Vec::new(), Vec::new());
    for _ in 0..24 {
        let [q, qd, qdd]: [[f64; 8]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| next()));
        let y = PandaMimic.regressor(&q, &qd, &qdd);
        let yb = PandaMimic.base_regressor(&q, &qd, &qdd);
        for (row, base) in y.iter().zip(&yb) {
            let row: Vec<f64> = row.iter().flatten().copied().collect();
            both.push([row.clone(), base.to_vec()].concat());
            links.push(row);
        }
    }
    (rank(&links), rank(&both))
}
