//! The worked examples of Niku, *Introduction to Robotics*, chapter 6, with the printed
//! numbers and formulas typed in by hand.

use crate::common::{load_robot, matrix4_error};
use dynamics_reference::nalgebra::{DMatrix, Matrix4};
use dynamics_reference::statics::{equivalent_wrench, joint_forces};
use dynamics_reference::{q_matrix, JointKind};
use dynamics_test_support::Rng;

fn assert_close(actual: f64, expected: f64, what: &str) {
    let err = (actual - expected).abs() / expected.abs().max(1.0);
    assert!(
        err < 1e-12,
        "{what}: got {actual}, expected {expected} (error {err:e})"
    );
}

/// Example 6.9: `T = ᴴJᵀ ᴴF` (eq. 6.64) with the printed Jacobian of a spherical-RPY
/// robot, a force of 1 lb along z and a moment of 20 lb·in about z of the hand frame.
#[test]
fn example_6_9_joint_forces_from_the_printed_jacobian() {
    #[rustfmt::skip]
    let jacobian = DMatrix::from_row_slice(6, 6, &[
        20.0, 0.0,  0.0, 0.0, 0.0, 0.0,
        -5.0, 0.0,  1.0, 0.0, 0.0, 0.0,
        0.0,  20.0, 0.0, 0.0, 0.0, 0.0,
        0.0,  1.0,  0.0, 0.0, 1.0, 0.0,
        0.0,  0.0,  0.0, 1.0, 0.0, 0.0,
        -1.0, 0.0,  0.0, 0.0, 0.0, 1.0,
    ]);
    let wrench = [0.0, 0.0, 1.0, 0.0, 0.0, 20.0];
    let t = joint_forces(&jacobian, wrench);
    // Printed answer: [T1, T2, F3, T4, T5, T6] = [-20, 20, 0, 0, 0, 20].
    assert_eq!(t.as_slice(), &[-20.0, 20.0, 0.0, 0.0, 0.0, 20.0]);
}

/// Example 6.10: force/moment relative to the reference frame, equivalent in frame B
/// (eq. 6.73). Printed answer ᴮf = [0, 0, 10], ᴮm = [−10, 80, 0].
#[test]
fn example_6_10_equivalent_wrench_in_frame_b() {
    #[rustfmt::skip]
    let b = Matrix4::new(
        0.0, 1.0, 0.0, 3.0,
        0.0, 0.0, 1.0, 5.0,
        1.0, 0.0, 0.0, 8.0,
        0.0, 0.0, 0.0, 1.0,
    );
    let wrench = [0.0, 10.0, 0.0, 0.0, 0.0, 20.0];
    let bw = equivalent_wrench(&b, wrench);
    assert_eq!(bw, [0.0, 0.0, 10.0, -10.0, 80.0, 0.0]);
}

/// The two wrenches of Example 6.10 do the same virtual work (eq. 6.69) for a rigid
/// displacement of the object, and the transformation is consistent with T = JᵀF.
#[test]
fn equivalent_wrench_preserves_virtual_work() {
    let mut rng = Rng::new(610);
    // A random frame B: rotation from a product of elementary rotations.
    let b = dynamics_reference::rot_z(rng.range(-3.0, 3.0))
        * dynamics_reference::rot_x(rng.range(-3.0, 3.0))
        * dynamics_reference::rot_z(rng.range(-3.0, 3.0));
    let mut b = b;
    b[(0, 3)] = rng.range(-2.0, 2.0);
    b[(1, 3)] = rng.range(-2.0, 2.0);
    b[(2, 3)] = rng.range(-2.0, 2.0);
    let w: Vec<f64> = rng.vector(6, -10.0, 10.0);
    let wrench = [w[0], w[1], w[2], w[3], w[4], w[5]];
    let bw = equivalent_wrench(&b, wrench);
    // A rigid-body velocity (v at the reference origin, ω) seen at B's origin in B's axes.
    let v = rng.vector(3, -1.0, 1.0);
    let omega = rng.vector(3, -1.0, 1.0);
    let p = [b[(0, 3)], b[(1, 3)], b[(2, 3)]];
    let v_at_p = [
        v[0] + omega[1] * p[2] - omega[2] * p[1],
        v[1] + omega[2] * p[0] - omega[0] * p[2],
        v[2] + omega[0] * p[1] - omega[1] * p[0],
    ];
    let in_b = |x: &[f64]| -> Vec<f64> {
        (0..3)
            .map(|c| (0..3).map(|r| b[(r, c)] * x[r]).sum())
            .collect()
    };
    let (bv, bomega) = (in_b(&v_at_p), in_b(&omega));
    let work_ref: f64 = (0..3).map(|i| w[i] * v[i] + w[i + 3] * omega[i]).sum();
    let work_b: f64 = (0..3).map(|i| bw[i] * bv[i] + bw[i + 3] * bomega[i]).sum();
    assert_close(work_b, work_ref, "virtual work");
}

/// Example 6.6 (symbolic): for the Stanford arm, `U_52 = A1 Q2 A2 A3 A4 A5`,
/// `U_53 = A1 A2 Q3 A3 A4 A5`, `U_63 = A1 A2 Q3 A3 A4 A5 A6` and
/// `U_635 = A1 A2 Q3 A3 A4 Q5 A5 A6` (book indices; the API is 0-based).
#[test]
fn example_6_6_stanford_u_matrices_are_products_with_q() {
    let robot = load_robot("stanford");
    assert_eq!(robot.joints[1].kind, JointKind::Revolute);
    assert_eq!(robot.joints[2].kind, JointKind::Prismatic);
    let mut rng = Rng::new(66);
    for _ in 0..5 {
        let mut q = rng.vector(6, -3.0, 3.0);
        q[2] = rng.range(-0.5, 1.0);
        let a: Vec<Matrix4<f64>> = (0..6).map(|i| robot.link_transform(i, q[i])).collect();
        let qm: Vec<Matrix4<f64>> = robot.joints.iter().map(|j| q_matrix(j.kind)).collect();
        // Book: A1..A6 = a[0]..a[5], Q2 = qm[1], Q3 = qm[2], Q5 = qm[4].
        let u52 = a[0] * qm[1] * a[1] * a[2] * a[3] * a[4];
        let u53 = a[0] * a[1] * qm[2] * a[2] * a[3] * a[4];
        let u63 = a[0] * a[1] * qm[2] * a[2] * a[3] * a[4] * a[5];
        let u635 = a[0] * a[1] * qm[2] * a[2] * a[3] * qm[4] * a[4] * a[5];
        let t5 = a[0] * a[1] * a[2] * a[3] * a[4];
        assert!(matrix4_error(&robot.frame(&q, 4), &t5) < 1e-15, "0T5");
        assert!(matrix4_error(&robot.u(&q, 4, 1), &u52) < 1e-15, "U52");
        assert!(matrix4_error(&robot.u(&q, 4, 2), &u53) < 1e-15, "U53");
        assert!(matrix4_error(&robot.u(&q, 5, 2), &u63) < 1e-15, "U63");
        assert!(matrix4_error(&robot.u2(&q, 5, 2, 4), &u635) < 1e-15, "U635");
        assert!(matrix4_error(&robot.u2(&q, 5, 4, 2), &u635) < 1e-15, "U653");
        // Zero for j > i (eq. 6.28) and for k > i (eq. 6.29).
        assert_eq!(robot.u(&q, 4, 5), Matrix4::zeros(), "U56");
        assert_eq!(robot.u2(&q, 3, 2, 4), Matrix4::zeros(), "U435");
        // ∂A_i/∂q_i = Q_i A_i (eqs. 6.23, 6.26) in the standard convention.
        for i in 0..6 {
            let err = matrix4_error(&robot.link_transform_derivative(i, q[i]), &(qm[i] * a[i]));
            assert!(err < 1e-15, "dA{}", i + 1);
        }
    }
}

/// Example 6.8: the printed `D_ij`, `D_ijk` and `D_i` of the planar RR arm with equal
/// links (`niku_2link`: l = 0.7, m1 = 2, m2 = 1.5, I1(act) = 0.05, I2(act) = 0.02,
/// gravity −y, g = 9.81), and its final T1 and T2 (T2 with erratum 1 of `docs/errata.md`
/// corrected: `I2(act) θ̈2`, printed `I2(act) θ̈1`).
#[test]
fn example_6_8_two_link_arm_coefficients() {
    let robot = load_robot("niku_2link");
    let (l, m1, m2, i1, i2, g) = (0.7, 2.0, 1.5, 0.05, 0.02, 9.81);
    assert_eq!(robot.joints[0].actuator_inertia, i1);
    assert_eq!(robot.joints[1].actuator_inertia, i2);

    // Pseudo-inertia printed in the example: J = [[m l²/3, 0, 0, −m l/2], 0, 0, [−m l/2, 0, 0, m]].
    for (i, m) in [(0, m1), (1, m2)] {
        #[rustfmt::skip]
        let j = Matrix4::new(
            m * l * l / 3.0, 0.0, 0.0, -m * l / 2.0,
            0.0,             0.0, 0.0, 0.0,
            0.0,             0.0, 0.0, 0.0,
            -m * l / 2.0,    0.0, 0.0, m,
        );
        let err = matrix4_error(&robot.pseudo_inertia(i), &j);
        assert!(err < 1e-15, "J{} ({err:e})", i + 1);
    }

    let mut rng = Rng::new(68);
    let mut states = vec![[0.0, 0.0], [0.3, -1.1], [std::f64::consts::FRAC_PI_2, 2.0]];
    states.extend((0..5).map(|_| [rng.range(-3.2, 3.2), rng.range(-3.2, 3.2)]));
    for q in states {
        let (t1, t2) = (q[0], q[1]);
        let (c1, c2, s2, c12) = (t1.cos(), t2.cos(), t2.sin(), (t1 + t2).cos());

        let d11 = (m1 / 3.0 + 4.0 / 3.0 * m2 + m2 * c2) * l * l;
        let d12 = (1.0 / 3.0 + 0.5 * c2) * m2 * l * l;
        let d22 = m2 * l * l / 3.0;
        let d112 = -0.5 * m2 * l * l * s2;
        let d122 = -0.5 * m2 * l * l * s2;
        let d211 = 0.5 * m2 * l * l * s2;
        let d1 = 0.5 * m1 * g * l * c1 + 0.5 * m2 * g * l * c12 + m2 * g * l * c1;
        let d2 = 0.5 * m2 * g * l * c12;

        // The mass matrix includes the actuator inertias on the diagonal.
        let m = robot.mass_matrix(&q);
        assert_close(m[(0, 0)] - i1, d11, "D11");
        assert_close(m[(0, 1)], d12, "D12");
        assert_close(m[(1, 0)], d12, "D21");
        assert_close(m[(1, 1)] - i2, d22, "D22");

        // christoffel(q)[i][(j, k)] = D_ijk (0-based).
        let d = robot.christoffel(&q);
        assert_close(d[0][(0, 0)], 0.0, "D111");
        assert_close(d[0][(0, 1)], d112, "D112");
        assert_close(d[0][(1, 0)], d112, "D121");
        assert_close(d[0][(1, 1)], d122, "D122");
        assert_close(d[1][(0, 0)], d211, "D211");
        assert_close(d[1][(0, 1)], 0.0, "D212");
        assert_close(d[1][(1, 0)], 0.0, "D221");
        assert_close(d[1][(1, 1)], 0.0, "D222");

        let gravity = robot.gravity_torques(&q);
        assert_close(gravity[0], d1, "D1");
        assert_close(gravity[1], d2, "D2");

        // Final equations of motion at a few velocities and accelerations.
        for (qd, qdd) in [([0.0, 0.0], [0.0, 0.0]), ([1.3, -0.7], [0.4, 2.5])] {
            let tau = robot.inverse_dynamics(&q, &qd, &qdd);
            let expected_t1 = d11 * qdd[0] + d12 * qdd[1] + d122 * qd[1] * qd[1]
                - m2 * l * l * s2 * qd[0] * qd[1]
                + d1
                + i1 * qdd[0];
            let expected_t2 = d12 * qdd[0] + d22 * qdd[1] + d211 * qd[0] * qd[0] + d2 + i2 * qdd[1];
            assert_close(tau[0], expected_t1, "T1");
            assert_close(tau[1], expected_t2, "T2");
            // The printed T2 has I2(act) θ̈1 instead (`docs/errata.md` #1): it differs by
            // I2(act) (θ̈2 − θ̈1) whenever the accelerations differ.
            let printed_t2 = expected_t2 - i2 * qdd[1] + i2 * qdd[0];
            assert_close(tau[1] - printed_t2, i2 * (qdd[1] - qdd[0]), "erratum 1");
        }
    }
}
