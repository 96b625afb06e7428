//! The generated kinematics against the book's method of `dynamics-reference` (the products
//! `A_1 ⋯ A_i` and the Jacobian from `U_nj = ∂ ⁰T_n/∂q_j`, eq. 6.28, with nalgebra): the hand
//! pose, every link pose, both Jacobians (the hand frame's ᴴJ as `[Rᵀ 0; 0 Rᵀ]` times the
//! base-frame one), `J̇ q̇` by central differences of the reference Jacobian along `q̇`, and
//! the statics `T = Jᵀ F` as the reference's `joint_forces`, on the reference robots at random
//! positions, in `f64` and `f32`.

use dynamics_reference::nalgebra::{self, DMatrix, Matrix4};
use dynamics_reference::{scaled_error, statics::joint_forces, Robot as Reference};
use dynamics_runtime::{Dynamics, Pose};
use dynamics_test_support::Rng;
use dynamics_tests::robots::{
    NikuPolar, NikuTwoLink, Panda, Puma560, Random1, Random2, Random5, Stanford, Ur5,
};

const TOLERANCE: f64 = 1e-12;

fn reference(file: &str) -> Reference {
    let path = format!("{}/data/{file}", env!("CARGO_MANIFEST_DIR"));
    Reference::from_json(&std::fs::read_to_string(path).expect("robot file")).expect("json")
}

fn pose_entries(p: &Pose<f64>) -> Vec<f64> {
    p.homogeneous().iter().flatten().copied().collect()
}

fn entries(m: &Matrix4<f64>) -> Vec<f64> {
    (0..4)
        .flat_map(|i| (0..4).map(move |j| m[(i, j)]))
        .collect()
}

fn rows<const N: usize>(j: &[[f64; N]; 6]) -> Vec<f64> {
    j.iter().flatten().copied().collect()
}

fn reference_rows(j: &DMatrix<f64>) -> Vec<f64> {
    (0..6)
        .flat_map(|i| (0..j.ncols()).map(move |c| j[(i, c)]))
        .collect()
}

/// `[Rᵀ 0; 0 Rᵀ] j`: a base-frame Jacobian in the hand's axes.
fn in_hand(t: &Matrix4<f64>, j: &DMatrix<f64>) -> DMatrix<f64> {
    let r_t = t.fixed_view::<3, 3>(0, 0).transpose();
    let mut out = j.clone();
    for half in [0, 3] {
        let part = r_t * j.rows(half, 3);
        out.rows_mut(half, 3).copy_from(&part);
    }
    out
}

fn assert_close(what: &str, got: &[f64], want: &[f64], tolerance: f64) {
    let e = scaled_error(got, want);
    assert!(
        e < tolerance,
        "{what} off by {e:e}\n got {got:?}\nwant {want:?}"
    );
}

fn check<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) {
    let reference = reference(file);
    let mut rng = Rng::new(17);
    for _ in 0..10 {
        let q: [f64; N] = core::array::from_fn(|_| rng.range(-3.0, 3.0));
        let qd: [f64; N] = core::array::from_fn(|_| rng.range(-2.0, 2.0));
        let wrench: [f64; 6] = core::array::from_fn(|_| rng.range(-5.0, 5.0));
        let t = reference.forward_kinematics(&q);
        assert_close(
            "hand pose",
            &pose_entries(&robot.hand_pose(&q)),
            &entries(&t),
            TOLERANCE,
        );
        for (i, pose) in robot.link_poses(&q).iter().enumerate() {
            let want = entries(&reference.frame(&q, i));
            assert_close("link pose", &pose_entries(pose), &want, TOLERANCE);
        }
        let j = reference.jacobian(&q);
        let in_base = robot.hand_jacobian_in_base(&q);
        assert_close("J in base", &rows(&in_base), &reference_rows(&j), TOLERANCE);
        let hj = in_hand(&t, &j);
        let in_hand_frame = robot.hand_jacobian_in_hand(&q);
        assert_close("ᴴJ", &rows(&in_hand_frame), &reference_rows(&hj), TOLERANCE);
        let torques = robot.joint_torques_for_hand_wrench(&q, &wrench);
        let want = joint_forces(&hj, wrench);
        assert_close("ᴴJᵀ F", &torques, want.as_slice(), TOLERANCE);
        let torques = robot.joint_torques_for_base_wrench(&q, &wrench);
        let want = joint_forces(&j, wrench);
        assert_close("Jᵀ F", &torques, want.as_slice(), TOLERANCE);
        // J̇ q̇ = dJ/dt q̇ along q(t) = q + t q̇, by central differences.
        let h = 1e-5;
        let at =
            |s: f64| reference.jacobian(&core::array::from_fn::<f64, N, _>(|i| q[i] + s * qd[i]));
        let dj = (at(h) - at(-h)) / (2.0 * h);
        let qd_vector = nalgebra::DVector::from_column_slice(&qd);
        let bias = &dj * &qd_vector;
        let got = robot.hand_acceleration_bias_in_base(&q, &qd);
        assert_close("J̇ q̇", &got, bias.as_slice(), 1e-7);
        let r_t = t.fixed_view::<3, 3>(0, 0).transpose();
        let (linear, angular) = (r_t * bias.rows(0, 3), r_t * bias.rows(3, 3));
        let want: Vec<f64> = linear.iter().chain(angular.iter()).copied().collect();
        let got = robot.hand_acceleration_bias_in_hand(&q, &qd);
        assert_close("J̇ q̇ in hand axes", &got, &want, 1e-7);
        // The linear rows: central differences of the generated hand position; virtual work:
        // the torques of a wrench do on δq the work the wrench does on J δq.
        for c in 0..N {
            let position = |s: f64| {
                let mut moved = q;
                moved[c] += s;
                robot.hand_pose(&moved).position
            };
            let (up, down) = (position(h), position(-h));
            let column: Vec<f64> = (0..3).map(|i| (up[i] - down[i]) / (2.0 * h)).collect();
            let want: Vec<f64> = (0..3).map(|i| in_base[i][c]).collect();
            assert_close("J by differences", &column, &want, 1e-8);
        }
        let dq: [f64; N] = core::array::from_fn(|_| rng.range(-1.0, 1.0));
        let joint_work: f64 = (0..N).map(|i| torques[i] * dq[i]).sum();
        let hand_work: f64 = (0..6)
            .map(|r| wrench[r] * (0..N).map(|c| in_base[r][c] * dq[c]).sum::<f64>())
            .sum();
        assert!((joint_work - hand_work).abs() < 1e-10 * (1.0 + hand_work.abs()));
        // f32: the same code in single precision.
        let q32 = q.map(|x| x as f32);
        let j32 = robot.hand_jacobian_in_base(&q32).map(|r| r.map(f64::from));
        assert_close("J in base, f32", &rows(&j32), &reference_rows(&j), 1e-4);
    }
}

/// Against Pinocchio 4.1.0 (`data/kinematics/`, made by its `make.py`): the hand's placement,
/// its Jacobian in `LOCAL_WORLD_ALIGNED` and `LOCAL`, and its classical acceleration at
/// `q̈ = 0` in both, to 1e-10; and the statics against the torques that hold a wrench applied as
/// an external load, `rnea(q, q̇, q̈) − rnea(q, q̇, q̈, fext)` (field `tau_external`).
fn pinocchio<R: Dynamics<N>, const N: usize>(robot: &R, name: &str) {
    let path = format!("{}/data/kinematics/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let data: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("data file")).expect("json");
    let numbers = |v: &serde_json::Value| -> Vec<f64> {
        let flat = |x: &serde_json::Value| match x.as_array() {
            Some(row) => row.iter().map(|y| y.as_f64().expect("number")).collect(),
            None => vec![x.as_f64().expect("number")],
        };
        v.as_array().expect("array").iter().flat_map(flat).collect()
    };
    let (mut worst, mut worst_load) = (0.0f64, 0.0f64);
    for s in data["samples"].as_array().expect("samples") {
        let q: [f64; N] = numbers(&s["q"]).try_into().expect("q");
        let qd: [f64; N] = numbers(&s["qd"]).try_into().expect("qd");
        let pose = robot.hand_pose(&q);
        let checks = [
            ("rotation", pose.rotation.concat(), numbers(&s["rotation"])),
            (
                "position",
                pose.position.to_vec(),
                numbers(&s["translation"]),
            ),
            (
                "J",
                rows(&robot.hand_jacobian_in_base(&q)),
                numbers(&s["jacobian_world_aligned"]),
            ),
            (
                "ᴴJ",
                rows(&robot.hand_jacobian_in_hand(&q)),
                numbers(&s["jacobian_local"]),
            ),
            (
                "J̇ q̇",
                robot.hand_acceleration_bias_in_base(&q, &qd).to_vec(),
                numbers(&s["bias_world_aligned"]),
            ),
            (
                "J̇ q̇ in hand axes",
                robot.hand_acceleration_bias_in_hand(&q, &qd).to_vec(),
                numbers(&s["bias_local"]),
            ),
        ];
        let loads = external_loads(robot, &q, s, &numbers);
        for (what, got, want) in checks.into_iter().chain(loads) {
            assert_close(&format!("{name}: {what}"), &got, &want, 1e-10);
            let e = scaled_error(&got, &want);
            worst = worst.max(e);
            if what.contains("load") {
                worst_load = worst_load.max(e);
            }
        }
    }
    eprintln!(
        "{name}: worst scaled error against Pinocchio {worst:.1e} (external load {worst_load:.1e})"
    );
}

type Check = (&'static str, Vec<f64>, Vec<f64>);

/// `T = ᴴJᵀ ᴴF` for the sample's hand-frame wrench, and `T = Jᵀ F` for the same wrench turned
/// into base axes, `[R f; R m]` with Pinocchio's hand rotation `R` (the moment stays about the
/// hand's origin), both against Pinocchio's `tau_external`.
fn external_loads<R: Dynamics<N>, const N: usize>(
    robot: &R,
    q: &[f64; N],
    sample: &serde_json::Value,
    numbers: &dyn Fn(&serde_json::Value) -> Vec<f64>,
) -> [Check; 2] {
    let wrench: [f64; 6] = numbers(&sample["wrench"]).try_into().expect("wrench");
    let rotation = numbers(&sample["rotation"]);
    let in_base: [f64; 6] = core::array::from_fn(|i| {
        let (half, row) = (i / 3 * 3, i % 3);
        (0..3)
            .map(|k| rotation[3 * row + k] * wrench[half + k])
            .sum()
    });
    let want = numbers(&sample["tau_external"]);
    [
        (
            "ᴴJᵀ F = τ of the load",
            robot.joint_torques_for_hand_wrench(q, &wrench).to_vec(),
            want.clone(),
        ),
        (
            "Jᵀ F in base = τ of the load",
            robot.joint_torques_for_base_wrench(q, &in_base).to_vec(),
            want,
        ),
    ]
}

#[test]
fn every_reference_robot_matches_pinocchio() {
    pinocchio(&Puma560, "puma560");
    pinocchio(&Stanford, "stanford");
    pinocchio(&Ur5, "ur5");
    pinocchio(&NikuTwoLink, "niku_2link");
    pinocchio(&NikuPolar, "niku_polar");
    pinocchio(&Random1, "random1");
    pinocchio(&Random2, "random2");
    pinocchio(&Random5, "random5");
    pinocchio(&Panda, "panda");
}

#[test]
fn puma560() {
    check(&Puma560, "reference/robots/puma560.json");
}

#[test]
fn stanford_arm_with_a_prismatic_joint() {
    check(&Stanford, "reference/robots/stanford.json");
}

#[test]
fn ur5() {
    check(&Ur5, "reference/robots/ur5.json");
}

#[test]
fn niku_polar_arm() {
    check(&NikuPolar, "reference/robots/niku_polar.json");
}

#[test]
fn random_robots() {
    check(&Random2, "reference/robots/random2.json");
    check(&Random5, "reference/robots/random5.json");
}

#[test]
fn panda_in_the_modified_convention() {
    check(&Panda, "panda/robot.json");
}

/// A 3-joint arm without a tool and the same with `tool = [..]`.
macro_rules! arm {
    ($name:ident $(, $tool:tt)?) => {
        #[derive(Dynamics)]
        #[dynamics(
            gravity = [0, 0, -9.81],
            dh = [[q, 0.3, 0.05, 90 deg], [q + 10 deg, 0, 0.4, 0], [q, 0.1, 0.02, -30 deg]],
            link(mass = 2), link(mass = 1.5), link(mass = 1),
            $(tool = $tool)?
        )]
        struct $name;
    };
}

arm!(Plain);
arm!(WithTool, [0.1, -0.05, 0.2, 30 deg, -90 deg, 45 deg]);

/// The tool frame is the hand frame followed by `Trans(xyz) Rz(yaw) Ry(pitch) Rx(roll)`
/// (built here with nalgebra's Euler angles), and its Jacobians those of that point.
#[test]
fn a_tool_transform_moves_the_hand_frame() {
    use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
    let deg = std::f64::consts::PI / 180.0;
    let tool = Isometry3::from_parts(
        Translation3::new(0.1, -0.05, 0.2),
        UnitQuaternion::from_euler_angles(30.0 * deg, -90.0 * deg, 45.0 * deg),
    )
    .to_homogeneous();
    let mut rng = Rng::new(3);
    for _ in 0..10 {
        let q: [f64; 3] = core::array::from_fn(|_| rng.range(-3.0, 3.0));
        let plain = Matrix4::from_fn(|i, j| Plain.hand_pose(&q).homogeneous()[i][j]);
        let want = plain * tool;
        let got = WithTool.hand_pose(&q).homogeneous();
        assert_close("tool pose", &got.concat(), &entries(&want), TOLERANCE);
        // The tool's origin moves with v + ω × r, r from the hand's origin to the tool's.
        let offset = (want - plain).fixed_view::<3, 1>(0, 3).into_owned();
        let j = Plain.hand_jacobian_in_base(&q);
        let mut shifted = DMatrix::from_fn(6, 3, |i, c| j[i][c]);
        for mut column in shifted.column_iter_mut() {
            let w = Vector3::new(column[3], column[4], column[5]);
            let v = Vector3::new(column[0], column[1], column[2]) + w.cross(&offset);
            column.fixed_rows_mut::<3>(0).copy_from(&v);
        }
        let got = WithTool.hand_jacobian_in_base(&q);
        assert_close("tool J", &rows(&got), &reference_rows(&shifted), TOLERANCE);
        let got = WithTool.hand_jacobian_in_hand(&q);
        let want = reference_rows(&in_hand(&want, &shifted));
        assert_close("tool ᴴJ", &rows(&got), &want, TOLERANCE);
    }
}
