//! NaN and infinite joint states and parameters never panic, in generated code nor in the
//! runtime's `sin_cos` (this is a debug build: overflow checks and debug assertions are on).
//! The results are then whatever IEEE arithmetic gives; only their absence of panics is
//! asserted, plus that a NaN input shows up in the outputs that depend on it.

use dynamics_runtime::{Dynamics, Real};

#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [[q, 0, l, 90 deg], [q + 0.3, 0, 0.4, 0], [0.2, q, 0, -90 deg]],
    link(mass = m, com = [-l / 2, 0, 0], inertia = [0.01, 0.1, 0.1, 0, 0, 0], spring = (k, 0.1)),
    link(mass = 2, com = [-0.2, 0.01, 0], inertia = [0.02, 0.1, 0.1, 0.001, 0, 0], actuator_inertia = 0.05),
    link(mass = 0.5, com = [0, 0, -0.1], inertia = [0.003, 0.003, 0.001, 0, 0, 0]),
)]
struct Arm {
    g: f64,
    l: f64,
    m: f32,
    k: f64,
}

const SPECIAL: [f64; 6] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::MAX,
    1e300,
    -0.0,
];

fn all_methods<T: Real>(arm: &Arm, q: &[T; 3], qd: &[T; 3], qdd: &[T; 3]) -> Vec<T> {
    let mut out = Vec::new();
    out.extend(arm.mass_matrix(q).into_iter().flatten());
    out.extend(arm.coriolis_matrix(q, qd).into_iter().flatten());
    out.extend(arm.coriolis_torques(q, qd));
    out.extend(arm.gravity_torques(q));
    out.extend(arm.bias_torques(q, qd));
    out.extend(arm.inverse_dynamics(q, qd, qdd));
    out.push(arm.kinetic_energy(q, qd));
    out.push(arm.potential_energy(q));
    out
}

#[test]
fn special_states_do_not_panic() {
    let arm = Arm {
        g: 9.81,
        l: 0.5,
        m: 1.5,
        k: 2.0,
    };
    for &x in &SPECIAL {
        for slot in 0..3 {
            let mut v = [0.3, -0.2, 0.1];
            v[slot] = x;
            let plain = [0.3, -0.2, 0.1];
            for (q, qd, qdd) in [(v, plain, plain), (plain, v, plain), (plain, plain, v)] {
                let out = all_methods(&arm, &q, &qd, &qdd);
                if x.is_nan() {
                    assert!(out.iter().any(|y| y.is_nan()), "NaN vanished: {out:?}");
                }
                #[allow(clippy::cast_possible_truncation)]
                let f = |a: [f64; 3]| a.map(|y| y as f32);
                let _ = all_methods(&arm, &f(q), &f(qd), &f(qdd));
            }
        }
    }
}

#[test]
fn special_parameters_do_not_panic() {
    for &x in &SPECIAL {
        #[allow(clippy::cast_possible_truncation)]
        let arms = [
            Arm {
                g: x,
                l: 0.5,
                m: 1.5,
                k: 2.0,
            },
            Arm {
                g: 9.81,
                l: x,
                m: 1.5,
                k: 2.0,
            },
            Arm {
                g: 9.81,
                l: 0.5,
                m: x as f32,
                k: 2.0,
            },
            Arm {
                g: 9.81,
                l: 0.5,
                m: 1.5,
                k: x,
            },
        ];
        for arm in &arms {
            let out = all_methods(arm, &[0.3f64, -0.2, 0.1], &[1.0; 3], &[1.0; 3]);
            if x.is_nan() {
                assert!(out.iter().any(|y| y.is_nan()), "NaN vanished: {out:?}");
            }
            let _ = all_methods(arm, &[0.3f32, -0.2, 0.1], &[1.0; 3], &[1.0; 3]);
        }
    }
}

#[test]
fn sin_cos_of_special_arguments() {
    for &x in &SPECIAL {
        let (s, c) = x.sin_cos();
        if x.is_finite() {
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
        }
        let (rs, rc) = Real::sin_cos(x);
        assert_eq!(rs.is_nan(), s.is_nan(), "{x}: {rs} vs std {s}");
        assert_eq!(rc.is_nan(), c.is_nan(), "{x}: {rc} vs std {c}");
        #[allow(clippy::cast_possible_truncation)]
        let (fs, fc) = Real::sin_cos(x as f32);
        assert_eq!(fs.is_nan(), (x as f32).sin().is_nan(), "{x}: {fs} {fc}");
        assert_eq!(fc.is_nan(), (x as f32).cos().is_nan(), "{x}: {fs} {fc}");
    }
    for x in [
        f64::MIN_POSITIVE,
        5e-324,
        -5e-324,
        65536.0,
        65_536.000_000_1,
        -1e17,
    ] {
        let (s, c) = Real::sin_cos(x);
        assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
    }
}
