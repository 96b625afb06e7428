//! Joint friction `τ_f,i = f_v q̇_i + f_c sign(q̇_i) + f_0` (`f_c tanh(q̇_i / ε)` smoothed) and
//! geared drives (actuator inertia `N² I_rotor`), derived, against hand formulas: the friction
//! torques of a two-joint arm, written out below; `τ` with friction equals `τ` of the same arm
//! without it plus those torques, at random states, in `f64` and `f32`; the smooth form tends to
//! the sign form as ε → 0; a rotor behind a gear adds `N² I_rotor` to `M`'s diagonal.

use dynamics_runtime::Dynamics;
use dynamics_test_support::Rng;
use dynamics_tests::robots::Rubbing;

/// The same arm without friction.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = 2, com = [-0.35, 0, 0], inertia = [0, 0.08, 0.08, 0, 0, 0]),
    link(mass = 1, com = [-0.25, 0, 0], inertia = [0, 0.02, 0.02, 0, 0, 0]),
)]
struct Smooth;

/// The friction torques of [`Rubbing`], by hand.
fn by_hand(arm: &Rubbing, qd: [f64; 2]) -> [f64; 2] {
    let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
    [
        0.3 * qd[0] + 1.5 * sign(qd[0]) - 0.2,
        arm.fv2 * qd[1] + 0.8 * (qd[1] / arm.eps).tanh(),
    ]
}

fn state(rng: &mut Rng) -> [[f64; 2]; 3] {
    [0, 1, 2].map(|_| [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)])
}

#[test]
fn friction_torques_are_the_hand_formula_and_add_to_tau() {
    let mut rng = Rng::new(16);
    for _ in 0..200 {
        let arm = Rubbing {
            fv2: rng.range(0.0, 1.0),
            eps: rng.range(0.01, 1.0),
        };
        let [q, qd, qdd] = state(&mut rng);
        let f = arm.friction_torques(&qd);
        let want = by_hand(&arm, qd);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let rigid = Smooth.inverse_dynamics(&q, &qd, &qdd);
        for i in 0..2 {
            assert!(
                (f[i] - want[i]).abs() < 1e-14,
                "joint {i}: {} vs {}",
                f[i],
                want[i]
            );
            assert!((tau[i] - rigid[i] - f[i]).abs() < 1e-12, "joint {i}");
        }
        // Friction leaves M, C and g alone.
        assert_eq!(arm.mass_matrix(&q), Smooth.mass_matrix(&q));
        assert_eq!(arm.bias_torques(&q, &qd), Smooth.bias_torques(&q, &qd));
        // f32: the same to single precision.
        let f32s = |v: [f64; 2]| v.map(|x| x as f32);
        let tau32 = arm.inverse_dynamics(&f32s(q), &f32s(qd), &f32s(qdd));
        let f32_ = arm.friction_torques(&f32s(qd));
        for i in 0..2 {
            let scale = 1.0 + tau[i].abs();
            assert!(
                (f64::from(tau32[i]) - tau[i]).abs() < 1e-4 * scale,
                "joint {i}"
            );
            assert!((f64::from(f32_[i]) - f[i]).abs() < 1e-5 * (1.0 + f[i].abs()));
        }
    }
}

#[test]
fn at_rest_coulomb_friction_is_zero() {
    let arm = Rubbing { fv2: 0.4, eps: 0.1 };
    assert_eq!(arm.friction_torques(&[0.0, 0.0]), [-0.2, 0.0]);
    assert_eq!(arm.friction_torques(&[-0.0f32, 0.0]), [-0.2, 0.0]);
    // Just off rest, the full Coulomb torque, either way.
    assert_eq!(arm.friction_torques(&[1e-300, 0.0])[0], 1.5 - 0.2);
    assert_eq!(arm.friction_torques(&[-1e-300, 0.0])[0], -1.5 - 0.2);
}

#[test]
fn smooth_friction_tends_to_the_sign_form() {
    // Joint 2's tanh(q̇/ε) against 0.8 sign(q̇) at |q̇| ≥ 0.05: the gap is 0.8 (1 − tanh(0.05/ε)).
    let mut previous = f64::INFINITY;
    for eps in [1e-1, 1e-2, 1e-3, 1e-4] {
        let arm = Rubbing { fv2: 0.0, eps };
        let mut worst = 0.0f64;
        for k in 1..=100 {
            let qd = 0.05 * f64::from(k) * if k % 2 == 0 { 1.0 } else { -1.0 };
            let f = arm.friction_torques(&[0.0, qd])[1];
            worst = worst.max((f - 0.8 * qd.signum()).abs());
        }
        let bound = 0.8 * (1.0 - (0.05 / eps).tanh()) + 1e-15;
        assert!(worst <= bound && worst <= previous, "ε = {eps}: {worst}");
        previous = worst;
    }
    assert!(previous < 1e-15);
}

#[test]
fn a_robot_without_friction_has_none() {
    assert_eq!(Smooth.friction_torques(&[1.0, -2.0]), [0.0, 0.0]);
    assert_eq!(Smooth.friction_torques(&[1.0f32, -2.0]), [0.0, 0.0]);
}

/// A rotor behind a gear on each joint: 1e-4 kg m² at 100:1, and at −50:1 (a reversed drive)
/// given as fields.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = 2, com = [-0.35, 0, 0], inertia = [0, 0.08, 0.08, 0, 0, 0],
         rotor_inertia = 0.0001, gear_ratio = 100),
    link(mass = 1, com = [-0.25, 0, 0], inertia = [0, 0.02, 0.02, 0, 0, 0],
         rotor_inertia = rotor, gear_ratio = ratio),
)]
struct Geared {
    rotor: f64,
    ratio: f64,
}

#[test]
fn a_geared_rotor_adds_n_squared_i_to_the_diagonal() {
    let mut rng = Rng::new(4);
    let arm = Geared {
        rotor: 3e-5,
        ratio: -50.0,
    };
    for _ in 0..50 {
        let [q, qd, qdd] = state(&mut rng);
        let (m, rigid) = (arm.mass_matrix(&q), Smooth.mass_matrix(&q));
        let added = [100.0 * 100.0 * 1e-4, 50.0 * 50.0 * 3e-5];
        for i in 0..2 {
            for j in 0..2 {
                let want = rigid[i][j] + if i == j { added[i] } else { 0.0 };
                assert!((m[i][j] - want).abs() < 1e-13, "M{i}{j}");
            }
        }
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let rigid = Smooth.inverse_dynamics(&q, &qd, &qdd);
        for i in 0..2 {
            assert!((tau[i] - rigid[i] - added[i] * qdd[i]).abs() < 1e-12);
        }
    }
}
