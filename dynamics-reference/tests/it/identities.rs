//! Structural identities of the Lagrangian dynamics, checked on every reference robot at
//! pseudo-random states (independently of the stored reference data).

use crate::common::{all_robots, matrix4_error, matrix_error, scaled_error};
use dynamics_reference::nalgebra::{DMatrix, DVector};
use dynamics_reference::{JointKind, Robot};
use dynamics_test_support::Rng;

/// Random state within the ranges of the reference data.
fn random_state(robot: &Robot, rng: &mut Rng) -> (Vec<f64>, Vec<f64>) {
    let q = robot
        .joints
        .iter()
        .map(|j| match j.kind {
            JointKind::Revolute => rng.range(-std::f64::consts::PI, std::f64::consts::PI),
            JointKind::Prismatic => rng.range(-0.5, 1.0),
        })
        .collect();
    let qd = rng.vector(robot.dof(), -2.0, 2.0);
    (q, qd)
}

fn shifted(q: &[f64], dir: &[f64], step: f64) -> Vec<f64> {
    q.iter().zip(dir).map(|(a, b)| a + step * b).collect()
}

fn unit(n: usize, k: usize) -> Vec<f64> {
    (0..n).map(|i| if i == k { 1.0 } else { 0.0 }).collect()
}

/// Central-difference derivative of a matrix-valued function along `dir`.
fn directional_derivative(
    f: impl Fn(&[f64]) -> DMatrix<f64>,
    q: &[f64],
    dir: &[f64],
) -> DMatrix<f64> {
    let h = 1e-6;
    (f(&shifted(q, dir, h)) - f(&shifted(q, dir, -h))) / (2.0 * h)
}

#[test]
fn christoffel_symbols_are_symmetric_and_mass_matrix_is_symmetric() {
    let mut rng = Rng::new(1);
    for robot in all_robots() {
        for _ in 0..3 {
            let (q, _) = random_state(&robot, &mut rng);
            let m = robot.mass_matrix(&q);
            let m_err = matrix_error(&m, &m.transpose());
            assert!(m_err < 1e-14, "{}: M not symmetric ({m_err:e})", robot.name);
            for (i, d_i) in robot.christoffel(&q).iter().enumerate() {
                let err = matrix_error(d_i, &d_i.transpose());
                assert!(
                    err < 1e-14,
                    "{}: D_{i}jk not symmetric ({err:e})",
                    robot.name
                );
            }
            // Positive semi-definite (UR5's point masses make M singular: its last
            // joint turns a point mass that sits on the joint axis).
            let eigen = m.clone().symmetric_eigen().eigenvalues;
            let scale = eigen.amax().max(1.0);
            assert!(
                eigen.min() >= -1e-12 * scale,
                "{}: M has a negative eigenvalue {}",
                robot.name,
                eigen.min()
            );
        }
    }
}

#[test]
fn mass_matrix_derivative_equals_c_plus_c_transpose() {
    let mut rng = Rng::new(2);
    let mut worst = 0.0_f64;
    for robot in all_robots() {
        for _ in 0..3 {
            let (q, qd) = random_state(&robot, &mut rng);
            let m_dot = directional_derivative(|x| robot.mass_matrix(x), &q, &qd);
            let c = robot.coriolis_matrix(&q, &qd);
            let err = matrix_error(&(&c + c.transpose()), &m_dot);
            worst = worst.max(err);
            assert!(err < 1e-7, "{}: Mdot != C + C^T ({err:e})", robot.name);
        }
    }
    eprintln!("worst |C + C^T - dM/dt| (central differences): {worst:.1e}");
}

#[test]
fn christoffel_symbols_match_derivatives_of_the_mass_matrix() {
    // D_ijk = ½ (∂M_ij/∂q_k + ∂M_ik/∂q_j − ∂M_jk/∂q_i)
    let mut rng = Rng::new(3);
    for robot in all_robots() {
        let n = robot.dof();
        let (q, _) = random_state(&robot, &mut rng);
        let dm: Vec<DMatrix<f64>> = (0..n)
            .map(|k| directional_derivative(|x| robot.mass_matrix(x), &q, &unit(n, k)))
            .collect();
        let d = robot.christoffel(&q);
        for i in 0..n {
            let expected = DMatrix::from_fn(n, n, |j, k| {
                0.5 * (dm[k][(i, j)] + dm[j][(i, k)] - dm[i][(j, k)])
            });
            let err = matrix_error(&d[i], &expected);
            assert!(err < 1e-7, "{}: D_{i}jk vs dM ({err:e})", robot.name);
        }
    }
}

#[test]
fn coriolis_matrix_times_velocity_equals_double_sum() {
    let mut rng = Rng::new(4);
    for robot in all_robots() {
        let (q, qd) = random_state(&robot, &mut rng);
        let via_matrix = robot.coriolis_matrix(&q, &qd) * DVector::from_column_slice(&qd);
        let err = scaled_error(
            via_matrix.as_slice(),
            robot.coriolis_torques(&q, &qd).as_slice(),
        );
        assert!(err < 1e-13, "{}: C qd vs double sum ({err:e})", robot.name);
    }
}

#[test]
fn kinetic_energy_is_half_qd_m_qd() {
    let mut rng = Rng::new(5);
    for robot in all_robots() {
        let (q, qd) = random_state(&robot, &mut rng);
        let v = DVector::from_column_slice(&qd);
        let expected = 0.5 * v.dot(&(robot.mass_matrix(&q) * &v));
        let err = scaled_error(&[robot.kinetic_energy(&q, &qd)], &[expected]);
        assert!(err < 1e-13, "{}: KE vs qd^T M qd / 2 ({err:e})", robot.name);
    }
}

#[test]
fn gravity_torques_are_the_gradient_of_the_potential_energy_with_springs() {
    let mut rng = Rng::new(6);
    for mut robot in all_robots() {
        // None of the reference robots has springs: add some to cover that term too.
        for joint in &mut robot.joints {
            joint.spring_stiffness = rng.range(0.0, 50.0);
            joint.spring_rest = rng.range(-0.5, 0.5);
        }
        let n = robot.dof();
        let (q, _) = random_state(&robot, &mut rng);
        let h = 1e-6;
        let gradient: Vec<f64> = (0..n)
            .map(|k| {
                let e = unit(n, k);
                (robot.potential_energy(&shifted(&q, &e, h))
                    - robot.potential_energy(&shifted(&q, &e, -h)))
                    / (2.0 * h)
            })
            .collect();
        let err = scaled_error(robot.gravity_torques(&q).as_slice(), &gradient);
        assert!(err < 1e-7, "{}: g vs dP/dq ({err:e})", robot.name);
    }
}

#[test]
fn equations_of_motion_equal_lagrange_equations_by_finite_differences() {
    // tau = d/dt(∂K/∂qd) − ∂K/∂q + ∂P/∂q along a short trajectory q(t) = q + qd t + ½ qdd t².
    let mut rng = Rng::new(7);
    for robot in all_robots() {
        let n = robot.dof();
        let (q, qd) = random_state(&robot, &mut rng);
        let qdd = rng.vector(n, -5.0, 5.0);
        let h = 1e-5;
        let state = |t: f64| -> (Vec<f64>, Vec<f64>) {
            let qt = (0..n)
                .map(|i| q[i] + qd[i] * t + 0.5 * qdd[i] * t * t)
                .collect();
            let qdt = (0..n).map(|i| qd[i] + qdd[i] * t).collect();
            (qt, qdt)
        };
        // ∂K/∂qd = M qd.
        let momentum = |t: f64| {
            let (qt, qdt) = state(t);
            robot.mass_matrix(&qt) * DVector::from_column_slice(&qdt)
        };
        let d_momentum = (momentum(h) - momentum(-h)) / (2.0 * h);
        let lagrange: Vec<f64> = (0..n)
            .map(|k| {
                let e = unit(n, k);
                let dk_dq = (robot.kinetic_energy(&shifted(&q, &e, h), &qd)
                    - robot.kinetic_energy(&shifted(&q, &e, -h), &qd))
                    / (2.0 * h);
                let dp_dq = (robot.potential_energy(&shifted(&q, &e, h))
                    - robot.potential_energy(&shifted(&q, &e, -h)))
                    / (2.0 * h);
                d_momentum[k] - dk_dq + dp_dq
            })
            .collect();
        let err = scaled_error(robot.inverse_dynamics(&q, &qd, &qdd).as_slice(), &lagrange);
        assert!(err < 1e-6, "{}: tau vs Lagrange ({err:e})", robot.name);
    }
}

#[test]
fn link_transform_derivatives_match_finite_differences_in_both_conventions() {
    let mut rng = Rng::new(8);
    for robot in all_robots() {
        let (q, _) = random_state(&robot, &mut rng);
        let h = 1e-6;
        for (i, &q_i) in q.iter().enumerate() {
            let fd =
                (robot.link_transform(i, q_i + h) - robot.link_transform(i, q_i - h)) / (2.0 * h);
            let err = matrix4_error(&robot.link_transform_derivative(i, q_i), &fd);
            assert!(err < 1e-8, "{}: dA_{i}/dq ({err:e})", robot.name);
            for j in 0..robot.dof() {
                let e = unit(robot.dof(), j);
                let fd = (robot.frame(&shifted(&q, &e, h), i)
                    - robot.frame(&shifted(&q, &e, -h), i))
                    / (2.0 * h);
                let err = matrix4_error(&robot.u(&q, i, j), &fd);
                assert!(err < 1e-8, "{}: U_{i}{j} ({err:e})", robot.name);
                for k in 0..robot.dof() {
                    let e = unit(robot.dof(), k);
                    let fd = (robot.u(&shifted(&q, &e, h), i, j)
                        - robot.u(&shifted(&q, &e, -h), i, j))
                        / (2.0 * h);
                    let err = matrix4_error(&robot.u2(&q, i, j, k), &fd);
                    assert!(err < 1e-7, "{}: U_{i}{j}{k} ({err:e})", robot.name);
                }
            }
        }
    }
}

#[test]
fn jacobian_maps_joint_velocity_to_frame_velocity() {
    // v = d/dt p, [ω]× = Ṙ Rᵀ, by central differences along q(t) = q + qd t.
    let mut rng = Rng::new(9);
    for robot in all_robots() {
        let (q, qd) = random_state(&robot, &mut rng);
        let h = 1e-6;
        let t_plus = robot.forward_kinematics(&shifted(&q, &qd, h));
        let t_minus = robot.forward_kinematics(&shifted(&q, &qd, -h));
        let t_dot = (t_plus - t_minus) / (2.0 * h);
        let t = robot.forward_kinematics(&q);
        let r = t.fixed_view::<3, 3>(0, 0);
        let w = t_dot.fixed_view::<3, 3>(0, 0) * r.transpose();
        let expected = [
            t_dot[(0, 3)],
            t_dot[(1, 3)],
            t_dot[(2, 3)],
            w[(2, 1)],
            w[(0, 2)],
            w[(1, 0)],
        ];
        let twist = robot.jacobian(&q) * DVector::from_column_slice(&qd);
        let err = scaled_error(twist.as_slice(), &expected);
        assert!(
            err < 1e-7,
            "{}: J qd vs frame velocity ({err:e})",
            robot.name
        );
    }
}

#[test]
fn from_json_fills_defaults_and_reports_errors() {
    let json = r#"{"name": "one", "convention": "modified", "gravity": [0, 0, -9.81],
        "joints": [{"type": "prismatic", "theta": 0.1, "d": 0.2, "a": 0.3, "alpha": 0.4,
                    "mass": 1.0, "com": [0, 0, 0], "inertia": [1, 1, 1, 0, 0, 0]}]}"#;
    let robot = Robot::from_json(json).expect("valid");
    assert_eq!(robot.description, "");
    assert_eq!(robot.joints[0].kind, JointKind::Prismatic);
    assert_eq!(robot.joints[0].actuator_inertia, 0.0);
    assert_eq!(robot.joints[0].spring_stiffness, 0.0);
    assert_eq!(robot.joints[0].spring_rest, 0.0);

    assert!(Robot::from_json("{").is_err());
    assert!(Robot::from_json(&json.replace("prismatic", "helical")).is_err());
    assert!(Robot::from_json(&json.replace("modified", "craig")).is_err());
    assert!(Robot::from_json(&json.replace("[0, 0, -9.81]", "[0, -9.81]")).is_err());
    assert!(Robot::from_json(&json.replace(r#""mass": 1.0,"#, "")).is_err());
}

#[test]
fn modified_convention_derivative_is_not_q_times_a() {
    // In Craig's form the joint motion is the last factor of A_i, so the book's
    // ∂A_i/∂q_i = Q_i A_i (eqs. 6.23, 6.26) does not hold; the crate uses X·Q·Z.
    let robot = crate::common::load_robot("random2");
    assert_eq!(robot.convention, dynamics_reference::Convention::Modified);
    for (i, joint) in robot.joints.iter().enumerate() {
        let q_i = 0.3;
        let q_a = dynamics_reference::q_matrix(joint.kind) * robot.link_transform(i, q_i);
        let err = matrix4_error(&robot.link_transform_derivative(i, q_i), &q_a);
        assert!(err > 1e-3, "joint {i}: Q A unexpectedly equals dA/dq");
    }
}
