//! The base parameters (`Equations::base_parameters`), found exactly from the closed form,
//! against numerical ranks from independent implementations:
//!
//! * the counts of the reference, Panda and URDF robots, rigid bodies alone, with the rotors'
//!   inertia, with viscous and Coulomb friction, with offsets, against the rank of Pinocchio's
//!   stacked regressor (`data/regressor/base_counts.json`, 1,000 states, SVD): among them
//!   issue 27's PUMA 560 36, 40, 52 and Franka Panda 43, 48, 62;
//! * `Y_B π_B` against Pinocchio's `Y π` plus the joints' columns at its samples;
//! * on random robots of 2 to 7 revolute and prismatic joints, against the numerical rank of the
//!   textbook method's torques (`dynamics-reference`): τ is linear in the parameters, so the
//!   torques at a set of states of robots that differ only in their inertial parameters span,
//!   in their differences, the stacked regressor's column space;
//! * the generated `DynamicsBaseParameters` (`base_parameters = true`): `Y_B π_B` against
//!   `inverse_dynamics`, in `f64` and `f32`.

use dynamics_codegen::model::Robot;
use dynamics_codegen::trace::base_parameters::JointColumns;
use dynamics_codegen::{derive, front};
use dynamics_reference::scaled_error;
use dynamics_runtime::{Dynamics, DynamicsBaseParameters, DynamicsRegressor};
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::robot_of;
use dynamics_tests::robots::{Panda, Puma560};
use nalgebra::DMatrix;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestRunner};
use serde_json::Value;

/// `tests/<path>`.
fn read(path: &str) -> String {
    let path = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The robots of `data/regressor/`, by the name the data give them, as the derive reads them.
fn robot(name: &str) -> Robot {
    let urdf = |file: &str, base: &str, tip: &str| {
        let path = format!("../robots/urdf/{file}");
        let chain = front::Chain {
            base: Some(base),
            tip: Some(tip),
            tips: &[],
        };
        front::load_urdf(&path, &read(&path), chain, true)
            .unwrap_or_else(|e| panic!("{path}: {e:?}"))
            .robot
    };
    match name {
        "ur5_urdf" => urdf("ur5.urdf", "base_link", "tool0"),
        "ur10_urdf" => urdf("ur10.urdf", "base_link", "tool0"),
        "panda_urdf" => urdf("panda.urdf", "panda_link0", "panda_link8"),
        "z1_urdf" => urdf("z1.urdf", "link00", "link06"),
        "so101_urdf" => urdf("so101.urdf", "base_link", "gripper_link"),
        _ => {
            let path = if name == "panda" {
                "data/panda/robot.json".to_string()
            } else {
                format!("data/reference/robots/{name}.json")
            };
            front::load(&path, &read(&path))
                .unwrap_or_else(|e| panic!("{path}: {e}"))
                .robot
        }
    }
}

/// The joint columns of `base_counts.json`'s selections, for every joint.
fn selection(name: &str, n: usize) -> Vec<JointColumns> {
    let rotors = name != "rigid_body";
    let friction = matches!(name, "with_viscous_and_coulomb" | "with_offset");
    let columns = JointColumns {
        actuator_inertia: rotors,
        viscous: friction,
        coulomb: friction,
        offset: name == "with_offset",
    };
    vec![columns; n]
}

#[test]
fn counts_agree_with_the_rank_of_pinocchios_regressor() {
    let counts: Value = serde_json::from_str(&read("data/regressor/base_counts.json")).unwrap();
    let robots = counts["robots"].as_object().unwrap();
    let mut checked = 0;
    for (name, entry) in robots {
        let robot = robot(name);
        let mut eq = derive(&robot);
        let n = eq.dof;
        for kind in [
            "rigid_body",
            "with_actuator_inertia",
            "with_viscous_and_coulomb",
            "with_offset",
        ] {
            let base = eq.base_parameters(&robot, &selection(kind, n)).unwrap();
            let rank = entry[kind]["rank"].as_u64().unwrap();
            assert_eq!(base.parameters.len() as u64, rank, "{name}, {kind}");
            checked += 1;
        }
    }
    assert_eq!(checked, 4 * 14);
    // Issue 27's counts, which the data also hold.
    let issue = &counts["issue_27"];
    for name in ["puma560", "panda"] {
        let ranks: Vec<u64> = [
            "rigid_body",
            "with_actuator_inertia",
            "with_viscous_and_coulomb",
        ]
        .iter()
        .map(|k| robots[name][*k]["rank"].as_u64().unwrap())
        .collect();
        let expected: Vec<u64> = issue[name]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap())
            .collect();
        assert_eq!(ranks, expected, "{name}");
    }
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .flat_map(|x| match x {
            Value::Array(_) => numbers(x),
            _ => vec![x.as_f64().unwrap()],
        })
        .collect()
}

#[test]
fn reduced_regressor_times_base_parameters_is_pinocchios_torque() {
    for name in [
        "puma560",
        "stanford",
        "panda",
        "random5",
        "ur10_urdf",
        "so101_urdf",
    ] {
        let robot = robot(name);
        let mut eq = derive(&robot);
        let n = eq.dof;
        let base = eq
            .base_parameters(&robot, &selection("with_offset", n))
            .unwrap();
        let data: Value =
            serde_json::from_str(&read(&format!("data/regressor/{name}.json"))).unwrap();
        let pi = numbers(&data["pi"]);
        let pi_extra = numbers(&data["pi_extra"]);
        // The description's own joint parameters are zero where it has none: π_B is checked
        // with the data's, put in the place of the description's through Y π.
        for sample in data["samples"].as_array().unwrap() {
            let (q, qd, qdd) = (
                numbers(&sample["q"]),
                numbers(&sample["qd"]),
                numbers(&sample["qdd"]),
            );
            let y = numbers(&sample["Y"]);
            let y_extra = numbers(&sample["Y_extra"]);
            let expected: Vec<f64> = (0..n)
                .map(|i| {
                    let links: f64 = (0..10 * n).map(|k| y[i * 10 * n + k] * pi[k]).sum();
                    let joints: f64 = (0..4 * n)
                        .map(|k| y_extra[i * 4 * n + k] * pi_extra[k])
                        .sum();
                    links + joints
                })
                .collect();
            let tau = vec![0.0; n];
            let state = State {
                q: &q,
                qd: &qd,
                qdd: &qdd,
                tau: &tau,
            };
            let values = evaluate(&eq, state);
            // π_B from the data's standard parameters, by the grouping's coefficients.
            let standard = |p: dynamics_codegen::trace::base_parameters::Parameter| match p {
                dynamics_codegen::trace::base_parameters::Parameter::Link { link, index } => {
                    pi[10 * link + index]
                }
                dynamics_codegen::trace::base_parameters::Parameter::Joint { joint, index } => {
                    pi_extra[4 * joint + index]
                }
            };
            let pi_base: Vec<f64> = base
                .parameters
                .iter()
                .map(|b| {
                    b.terms
                        .iter()
                        .map(|t| t.coefficient.to_f64() * standard(t.parameter))
                        .sum()
                })
                .collect();
            let tau: Vec<f64> = (0..n)
                .map(|i| {
                    let row = &base.regressor[i];
                    row.iter()
                        .zip(&pi_base)
                        .map(|(id, p)| values[id.index()] * p)
                        .sum()
                })
                .collect();
            let error = scaled_error(&tau, &expected);
            assert!(error < 1e-10, "{name}: error {error:e}");
        }
    }
}

/// The numerical rank of `w`'s columns scaled to unit norm: singular values above 1e-8 times
/// the largest, with the gap to the first one dropped, which must be wide for the rank to mean
/// anything.
fn numerical_rank(w: &DMatrix<f64>) -> (usize, f64) {
    let mut w = w.clone();
    for mut column in w.column_iter_mut() {
        let norm = column.norm();
        if norm > 0.0 {
            column /= norm;
        }
    }
    let mut sigma: Vec<f64> = w.singular_values().iter().copied().collect();
    sigma.sort_by(|a, b| b.total_cmp(a));
    let largest = sigma[0];
    let rank = sigma.iter().filter(|s| **s > 1e-8 * largest).count();
    let gap = if rank < sigma.len() {
        sigma[rank - 1] / sigma[rank].max(f64::MIN_POSITIVE)
    } else {
        f64::INFINITY
    };
    (rank, gap)
}

#[test]
fn random_robots_against_the_rank_of_the_textbook_methods_torques() {
    let config = Config {
        cases: 16,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(2027),
        ..Config::default()
    };
    let seen = std::cell::RefCell::new([0_usize; 8]);
    let result = TestRunner::new(config).run(&robot_of(2..=7), |spec| {
        let n = spec.joints.len();
        seen.borrow_mut()[n] += 1;
        let model = spec.model();
        let mut eq = derive(&model);
        let with_rotors = vec![
            JointColumns {
                actuator_inertia: true,
                ..JointColumns::default()
            };
            n
        ];
        let exact = eq.base_parameters(&model, &with_rotors).unwrap();
        // Variants of the robot's inertial parameters, more than there are parameters, and
        // states enough for every parameter to show.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1_u64 << 53) as f64
        };
        let variants: Vec<_> = (0..=11 * n + 4)
            .map(|_| spec.with_inertials(&mut uniform).reference())
            .collect();
        let states: Vec<[Vec<f64>; 3]> = (0..20)
            .map(|_| {
                [0; 3].map(|k| {
                    let scale = [std::f64::consts::PI, 2.0, 5.0][k];
                    (0..n).map(|_| scale * (2.0 * uniform() - 1.0)).collect()
                })
            })
            .collect();
        let torques = |robot: &dynamics_reference::Robot| -> Vec<f64> {
            states
                .iter()
                .flat_map(|[q, qd, qdd]| {
                    robot
                        .inverse_dynamics(q, qd, qdd)
                        .iter()
                        .copied()
                        .collect::<Vec<_>>()
                })
                .collect()
        };
        let first = torques(&variants[0]);
        let columns: Vec<Vec<f64>> = variants[1..]
            .iter()
            .map(|v| torques(v).iter().zip(&first).map(|(a, b)| a - b).collect())
            .collect();
        let w = DMatrix::from_fn(first.len(), columns.len(), |i, j| columns[j][i]);
        let (rank, gap) = numerical_rank(&w);
        proptest::prop_assert!(gap > 1e4, "no clear numerical rank: gap {gap:e}");
        proptest::prop_assert_eq!(exact.parameters.len(), rank, "{} joints", n);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let seen = seen.into_inner();
    assert!(
        seen[2..].iter().all(|&k| k > 0),
        "robots of every size: {seen:?}"
    );
}

/// `Y_B π_B` of a robot at a state (a robot with mimic joints has `L` links past its `N`
/// coordinates).
pub(crate) fn predicted<R, const N: usize, const B: usize, const L: usize>(
    robot: &R,
    q: &[f64; N],
    qd: &[f64; N],
    qdd: &[f64; N],
) -> Vec<f64>
where
    R: DynamicsBaseParameters<N, B, L>,
{
    let y = robot.base_regressor(q, qd, qdd);
    // Written in place, every element of a buffer that held something else, bit for bit.
    let mut into = [[f64::NAN; B]; N];
    robot.base_regressor_into(q, qd, qdd, &mut into);
    let bits = |y: &[[f64; B]; N]| y.iter().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&into), bits(&y));
    let pi = robot.base_parameters::<f64>();
    y.iter()
        .map(|row| row.iter().zip(&pi).map(|(a, b)| a * b).sum())
        .collect()
}

fn generated_against_inverse_dynamics<R, const N: usize, const B: usize>(robot: &R, name: &str)
where
    R: DynamicsBaseParameters<N, B>,
{
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1_u64 << 53) as f64 * 2.0 - 1.0
    };
    for _ in 0..20 {
        let q: [f64; N] = std::array::from_fn(|_| 3.0 * uniform());
        let qd: [f64; N] = std::array::from_fn(|_| 2.0 * uniform());
        let qdd: [f64; N] = std::array::from_fn(|_| 5.0 * uniform());
        let tau = robot.inverse_dynamics(&q, &qd, &qdd);
        let error = scaled_error(&predicted(robot, &q, &qd, &qdd), &tau);
        assert!(error < 1e-12, "{name}: error {error:e}");
    }
}

#[test]
fn generated_base_regressor_times_base_parameters_is_inverse_dynamics() {
    // Neither description gives actuator inertia or friction: the links' alone, as counted.
    generated_against_inverse_dynamics::<_, 6, 36>(&Puma560, "puma560");
    generated_against_inverse_dynamics::<_, 7, 43>(&Panda, "panda");
    // As many as the exact analysis finds.
    let robot = robot("panda");
    let mut eq = derive(&robot);
    let described: Vec<JointColumns> = robot.joints.iter().map(JointColumns::described).collect();
    assert_eq!(
        eq.base_parameters(&robot, &described)
            .unwrap()
            .parameters
            .len(),
        43
    );
}

#[test]
fn generated_base_regressor_in_f32() {
    let q = [0.3_f32, -0.7, 1.1, 0.2, -0.4, 0.9];
    let (qd, qdd) = ([0.5_f32; 6], [-1.0_f32; 6]);
    let narrow = Puma560.base_regressor(&q, &qd, &qdd);
    let wide = Puma560.base_regressor(&q.map(f64::from), &qd.map(f64::from), &qdd.map(f64::from));
    let narrow: Vec<f64> = narrow.iter().flatten().map(|&x| f64::from(x)).collect();
    let wide: Vec<f64> = wide.iter().flatten().copied().collect();
    assert!(scaled_error(&narrow, &wide) < 1e-5);
}

/// Masses and inertias may be struct fields: the grouping depends on the geometry alone.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 1, 0], [q, 0, 0.5, 0]],
    link(mass = 1),
    link(mass = mass, inertia = [0, 0, inertia, 0, 0, 0]),
    base_parameters = true
)]
struct Planar {
    mass: f64,
    inertia: f64,
}

#[test]
fn base_parameters_of_field_masses() {
    for (mass, inertia) in [(2.0, 0.1), (3.5, 0.02)] {
        let arm = Planar { mass, inertia };
        let (q, qd, qdd) = ([0.3, -1.2], [0.7, 0.4], [-2.0, 1.5]);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let error = scaled_error(&predicted(&arm, &q, &qd, &qdd), &tau);
        assert!(error < 1e-12, "error {error:e}");
    }
}

/// `P π + P_J p` with the maps of `base_from_standard` and `base_from_joints`.
fn mapped<R, const N: usize, const B: usize>(
    robot: &R,
    pi: &[[f64; 10]; N],
    joints: &[[f64; 4]; N],
) -> [f64; B]
where
    R: DynamicsBaseParameters<N, B>,
{
    let (p, pj) = (
        robot.base_from_standard::<f64>(),
        robot.base_from_joints::<f64>(),
    );
    std::array::from_fn(|b| {
        let links: f64 = (0..N)
            .map(|j| (0..10).map(|k| p[b][j][k] * pi[j][k]).sum::<f64>())
            .sum();
        let own: f64 = (0..N)
            .map(|i| (0..4).map(|k| pj[b][i][k] * joints[i][k]).sum::<f64>())
            .sum();
        links + own
    })
}

#[test]
fn the_map_from_standard_parameters() {
    let robot = Puma560;
    let (pi, joints) = (
        robot.standard_parameters::<f64>(),
        robot.joint_parameters::<f64>(),
    );
    let base: [f64; 36] = robot.base_parameters();
    assert!(scaled_error(&mapped(&robot, &pi, &joints), &base) < 1e-14);
    // Other standard parameters, not physical ones: Y_B (P π') is still Y π'.
    let other: [[f64; 10]; 6] =
        std::array::from_fn(|j| std::array::from_fn(|k| ((7 * j + 3 * k) % 11) as f64 - 5.0));
    let mapped: [f64; 36] = mapped(&robot, &other, &joints);
    let (q, qd, qdd) = ([0.4, -0.9, 1.3, 0.1, 0.8, -0.5], [0.6; 6], [-1.2; 6]);
    let y = robot.regressor(&q, &qd, &qdd);
    let yb = robot.base_regressor(&q, &qd, &qdd);
    let full: Vec<f64> = (0..6)
        .map(|i| {
            (0..6)
                .map(|j| (0..10).map(|k| y[i][j][k] * other[j][k]).sum::<f64>())
                .sum()
        })
        .collect();
    let reduced: Vec<f64> = yb
        .iter()
        .map(|row| row.iter().zip(&mapped).map(|(a, b)| a * b).sum())
        .collect();
    assert!(scaled_error(&reduced, &full) < 1e-12);
}
