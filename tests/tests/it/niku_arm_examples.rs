//! The worked examples of Niku, *Introduction to Robotics*, ch. 6, on robot arms (Examples
//! 6.4, 6.5 and 6.8: two-link arms of rods, a polar arm, actuator inertias), each derived from a
//! D-H table with `#[derive(Dynamics)]` and checked against the book's PRINTED equations of
//! motion, typed in below by hand (corrected where `docs/errata.md` says so), at many random
//! states with random parameters. The harness, and what it checks, is `dynamics_tests::book`;
//! Examples 6.1–6.3 are in `niku_lagrangian_examples.rs`.

use dynamics_runtime::Dynamics;
use dynamics_tests::book::{add, check, mv2, Book, Joint, TOLERANCE};

// ---------------------------------------------------------------------------------------------
// Example 6.4: 2R arm of uniform rods (CoM at mid-length), angles from the horizontal x0.
// ---------------------------------------------------------------------------------------------

/// Rods along x_i with the CoM at −l_i/2 in frame i, I = m l²/12 about y_i and z_i, gravity −y0.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ   d   a    α
        [   q,  0,  l1,  0 ],
        [   q,  0,  l2,  0 ],
    ],
    link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0, m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0]),
    link(mass = m2, com = [-l2 / 2, 0, 0], inertia = [0, m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0]),
)]
struct RodArm {
    l1: f64,
    l2: f64,
    m1: f64,
    m2: f64,
    g: f64,
}

/// Example 6.4: eqs. (6.11), (6.12) and the matrix form (6.13); K from (6.9), P from (6.10)
/// (datum at the base). Ṁ: d/dt (m2 l1 l2 C2) = −m2 l1 l2 S2 θ̇2,
/// d/dt (½ m2 l1 l2 C2) = −½ m2 l1 l2 S2 θ̇2. No errata.
#[test]
fn example_6_4_two_link_rods() {
    let worst = check("6.4", 64, [Joint::Revolute, Joint::Revolute], |rng| {
        let (l1, l2) = (rng.range(0.2, 2.0), rng.range(0.2, 2.0));
        let (m1, m2, g) = (
            rng.range(0.5, 5.0),
            rng.range(0.5, 5.0),
            rng.range(1.0, 20.0),
        );
        let book = Book::new(move |q, qd, qdd| {
                let (c1, c2, s2, c12) = (q[0].cos(), q[1].cos(), q[1].sin(), (q[0] + q[1]).cos());
                let [t1d, t2d] = *qd;
                let [t1dd, t2dd] = *qdd;
                [
                    // (6.11)
                    (m1 * l1 * l1 / 3.0
                        + m2 * l1 * l1
                        + m2 * l2 * l2 / 3.0
                        + m2 * l1 * l2 * c2)
                        * t1dd
                        + (m2 * l2 * l2 / 3.0 + m2 * l1 * l2 * c2 / 2.0) * t2dd
                        - m2 * l1 * l2 * s2 * t1d * t2d
                        - m2 * l1 * l2 * s2 * t2d * t2d / 2.0
                        + (m1 / 2.0 + m2) * g * l1 * c1
                        + m2 * g * l2 * c12 / 2.0,
                    // (6.12)
                    (m2 * l2 * l2 / 3.0 + m2 * l1 * l2 * c2 / 2.0) * t1dd
                        + m2 * l2 * l2 * t2dd / 3.0
                        + m2 * l1 * l2 * s2 * t1d * t1d / 2.0
                        + m2 * g * l2 * c12 / 2.0,
                ]
            })
            // (6.13)
            .mass(move |q| {
                let c2 = q[1].cos();
                let m12 = m2 * l2 * l2 / 3.0 + m2 * l1 * l2 * c2 / 2.0;
                [
                    [
                        m1 * l1 * l1 / 3.0
                            + m2 * l1 * l1
                            + m2 * l2 * l2 / 3.0
                            + m2 * l1 * l2 * c2,
                        m12,
                    ],
                    [m12, m2 * l2 * l2 / 3.0],
                ]
            })
            .velocity(move |q, qd| {
                let h = m2 * l1 * l2 * q[1].sin() / 2.0;
                let [t1d, t2d] = *qd;
                add(
                    &mv2([[0.0, -h], [h, 0.0]], [t1d * t1d, t2d * t2d]),
                    &mv2([[-h, -h], [0.0, 0.0]], [t1d * t2d, t2d * t1d]),
                )
            })
            .gravity(move |q| {
                let (c1, c12) = (q[0].cos(), (q[0] + q[1]).cos());
                [
                    (m1 / 2.0 + m2) * g * l1 * c1 + m2 * g * l2 * c12 / 2.0,
                    m2 * g * l2 * c12 / 2.0,
                ]
            })
            .mass_dot(move |q, qd| {
                let d = -m2 * l1 * l2 * q[1].sin() * qd[1];
                [[d, d / 2.0], [d / 2.0, 0.0]]
            })
            // (6.9)
            .kinetic(move |q, qd| {
                let c2 = q[1].cos();
                let [t1d, t2d] = *qd;
                t1d * t1d
                    * (m1 * l1 * l1 / 6.0
                        + m2 * l2 * l2 / 6.0
                        + m2 * l1 * l1 / 2.0
                        + m2 * l1 * l2 * c2 / 2.0)
                    + t2d * t2d * (m2 * l2 * l2 / 6.0)
                    + t1d * t2d * (m2 * l2 * l2 / 3.0 + m2 * l1 * l2 * c2 / 2.0)
            })
            // (6.10)
            .potential(move |q| {
                let (s1, s12) = (q[0].sin(), (q[0] + q[1]).sin());
                m1 * g * l1 / 2.0 * s1 + m2 * g * (l1 * s1 + l2 / 2.0 * s12)
            });
        (RodArm { l1, l2, m1, m2, g }, book)
    });
    assert!(worst <= TOLERANCE);
}

// ---------------------------------------------------------------------------------------------
// Example 6.5: polar R-P arm; θ from x0, r = distance from the base A to the CoM D of the
// sliding link.
// ---------------------------------------------------------------------------------------------

/// As in the shared reference data's README ("Example 6.5 (polar arm) in D-H form"): z1 points
/// along the arm, y1 = z0 is the rotation axis, frame 2's origin is D, q2 = r.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ            d   a   α
        [   q + 90 deg,  0,  0,  90 deg ],
        [   0,           q,  0,  0      ],
    ],
    link(mass = m1, com = [0, 0, l1 / 2], inertia = [m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0, 0]),
    link(mass = m2, inertia = [m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0, 0]),
)]
struct PolarArm {
    l1: f64,
    l2: f64,
    m1: f64,
    m2: f64,
    g: f64,
}

/// Example 6.5: eqs. (6.14), (6.15) and the matrix form (6.16); the printed
/// K = (⅙ m1 l1² + 1/24 m2 l2² + ½ m2 r²) θ̇² + ½ m2 ṙ² and P = m1 g (l1/2) Sθ + m2 g r Sθ.
/// Ṁ: d/dt (m2 r²) = 2 m2 r ṙ. Erratum 2 (`docs/errata.md`) concerns only the intermediate d/dt(∂L/∂θ̇) line;
/// (6.14) is used as printed.
#[test]
fn example_6_5_polar_arm() {
    let worst = check("6.5", 65, [Joint::Revolute, Joint::Prismatic], |rng| {
        let (l1, l2) = (rng.range(0.2, 2.0), rng.range(0.2, 2.0));
        let (m1, m2, g) = (
            rng.range(0.5, 5.0),
            rng.range(0.5, 5.0),
            rng.range(1.0, 20.0),
        );
        let book = Book::new(move |q, qd, qdd| {
                let [th, r] = *q;
                let [thd, rd] = *qd;
                let [thdd, rdd] = *qdd;
                let (s, c) = th.sin_cos();
                [
                    // (6.14)
                    (m1 * l1 * l1 / 3.0 + m2 * l2 * l2 / 12.0 + m2 * r * r) * thdd
                        + 2.0 * m2 * r * rd * thd
                        + (m1 * g * l1 / 2.0 + m2 * g * r) * c,
                    // (6.15)
                    m2 * rdd - m2 * r * thd * thd + m2 * g * s,
                ]
            })
            // (6.16)
            .mass(move |q| {
                let r = q[1];
                [
                    [m1 * l1 * l1 / 3.0 + m2 * l2 * l2 / 12.0 + m2 * r * r, 0.0],
                    [0.0, m2],
                ]
            })
            .velocity(move |q, qd| {
                let r = q[1];
                let [thd, rd] = *qd;
                add(
                    &mv2([[0.0, 0.0], [-m2 * r, 0.0]], [thd * thd, rd * rd]),
                    &mv2([[m2 * r, m2 * r], [0.0, 0.0]], [rd * thd, thd * rd]),
                )
            })
            .gravity(move |q| {
                let [th, r] = *q;
                [(m1 * g * l1 / 2.0 + m2 * g * r) * th.cos(), m2 * g * th.sin()]
            })
            .mass_dot(move |q, qd| [[2.0 * m2 * q[1] * qd[1], 0.0], [0.0, 0.0]])
            .kinetic(move |q, qd| {
                let r = q[1];
                let [thd, rd] = *qd;
                (m1 * l1 * l1 / 6.0 + m2 * l2 * l2 / 24.0 + m2 * r * r / 2.0) * thd * thd
                    + m2 * rd * rd / 2.0
            })
            .potential(move |q| {
                let [th, r] = *q;
                m1 * g * l1 / 2.0 * th.sin() + m2 * g * r * th.sin()
            });
        (PolarArm { l1, l2, m1, m2, g }, book)
    });
    assert!(worst <= TOLERANCE);
}

// ---------------------------------------------------------------------------------------------
// Example 6.8: Example 6.4 with equal links (l1 = l2 = l) and actuator inertias, by the
// book's D_ij, D_ijk, D_i (eqs. 6.43–6.46).
// ---------------------------------------------------------------------------------------------

/// The D-H table printed in Example 6.8 (d = 0, a1 = a2 = l, α = 0), J1, J2 as printed
/// (CoM at −l/2 on x_i, ∫x² dm = ⅓ m l²), gᵀ = [0, −g, 0, 0].
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ   d   a   α
        [   q,  0,  l,  0 ],
        [   q,  0,  l,  0 ],
    ],
    link(mass = m1, com = [-l / 2, 0, 0], inertia = [0, m1 * l^2 / 12, m1 * l^2 / 12, 0, 0, 0],
         actuator_inertia = i1),
    link(mass = m2, com = [-l / 2, 0, 0], inertia = [0, m2 * l^2 / 12, m2 * l^2 / 12, 0, 0, 0],
         actuator_inertia = i2),
)]
struct NikuArm {
    l: f64,
    m1: f64,
    m2: f64,
    g: f64,
    i1: f64,
    i2: f64,
}

/// Example 6.8: the printed final T1 and T2, **T2 corrected per erratum 1 of
/// `docs/errata.md`** (its actuator term is I2(act) θ̈2, printed I2(act) θ̈1);
/// M = [D_ij] + diag(I1(act), I2(act)) with the printed D11, D12 = D21, D22 (eqs. 6.42/6.46);
/// the printed D_ijk as Christoffel symbols, C_ij = Σ_k D_ijk q̇_k, and the velocity terms
/// Σ_jk D_ijk q̇_j q̇_k of (6.46); the printed D1, D2. K = ½ Σ D_ij q̇_i q̇_j + ½ Σ I_i(act) q̇_i²
/// (6.38, 6.39 with 6.43); P from (6.10) with l1 = l2 = l (the book: "the same as Eqs. (6.11)
/// and (6.12)"). Ṁ: d/dt (m2 l² C2) = −m2 l² S2 θ̇2.
#[test]
fn example_6_8_two_link_actuators() {
    let worst = check("6.8", 68, [Joint::Revolute, Joint::Revolute], |rng| {
        let l = rng.range(0.2, 2.0);
        let (m1, m2, g) = (
            rng.range(0.5, 5.0),
            rng.range(0.5, 5.0),
            rng.range(1.0, 20.0),
        );
        let (i1, i2) = (rng.range(0.0, 0.5), rng.range(0.0, 0.5));
        let robot = NikuArm {
            l,
            m1,
            m2,
            g,
            i1,
            i2,
        };
        let book = example_6_8_book(&robot);
        (robot, book)
    });
    assert!(worst <= TOLERANCE);
}

/// The formulas Example 6.8 prints, for one parameter set (see the test above).
fn example_6_8_book(robot: &NikuArm) -> Book<2> {
    let NikuArm {
        l,
        m1,
        m2,
        g,
        i1,
        i2,
    } = *robot;
    let ll = l * l;
    // The printed D11, D12 = D21, D22.
    let d = move |q: &[f64; 2]| {
        let c2 = q[1].cos();
        let d12 = m2 * ll / 3.0 + m2 * ll * c2 / 2.0;
        [
            [m1 * ll / 3.0 + 4.0 * m2 * ll / 3.0 + m2 * ll * c2, d12],
            [d12, m2 * ll / 3.0],
        ]
    };
    // The printed D_ijk: D111 = 0, D112 = D121 = −½ m2 l² S2, D122 = −½ m2 l² S2,
    // D211 = ½ m2 l² S2, D212 = D221 = D222 = 0.
    let dijk = move |q: &[f64; 2]| {
        let h = m2 * ll * q[1].sin() / 2.0;
        [[[0.0, -h], [-h, -h]], [[h, 0.0], [0.0, 0.0]]]
    };
    // The printed D1, D2.
    let di = move |q: &[f64; 2]| {
        let (c1, c12) = (q[0].cos(), (q[0] + q[1]).cos());
        [
            m1 * g * l * c1 / 2.0 + m2 * g * l * c12 / 2.0 + m2 * g * l * c1,
            m2 * g * l * c12 / 2.0,
        ]
    };
    Book::new(move |q, qd, qdd| {
        let (c1, c2, s2, c12) = (q[0].cos(), q[1].cos(), q[1].sin(), (q[0] + q[1]).cos());
        let [t1d, t2d] = *qd;
        let [t1dd, t2dd] = *qdd;
        [
            (m1 * ll / 3.0 + 4.0 * m2 * ll / 3.0 + m2 * ll * c2) * t1dd
                + (m2 * ll / 3.0 + m2 * ll * c2 / 2.0) * t2dd
                - m2 * ll * s2 * t2d * t2d / 2.0
                - m2 * ll * s2 * t1d * t2d
                + m1 * g * l * c1 / 2.0
                + m2 * g * l * c12 / 2.0
                + m2 * g * l * c1
                + i1 * t1dd,
            (m2 * ll / 3.0 + m2 * ll * c2 / 2.0) * t1dd
                + m2 * ll * t2dd / 3.0
                + m2 * ll * s2 * t1d * t1d / 2.0
                + m2 * g * l * c12 / 2.0
                + i2 * t2dd, // docs/errata.md #1: printed `I2(act) θ̈1`
        ]
    })
    .mass(move |q| {
        let mut m = d(q);
        m[0][0] += i1;
        m[1][1] += i2;
        m
    })
    .velocity(move |q, qd| {
        let dq = dijk(q);
        core::array::from_fn(|i| {
            (0..2)
                .flat_map(|j| (0..2).map(move |k| (j, k)))
                .map(|(j, k)| dq[i][j][k] * qd[j] * qd[k])
                .sum()
        })
    })
    .gravity(di)
    .christoffel(dijk)
    .mass_dot(move |q, qd| {
        let h = -m2 * ll * q[1].sin() * qd[1];
        [[h, h / 2.0], [h / 2.0, 0.0]]
    })
    .kinetic(move |q, qd| {
        let m = d(q);
        0.5 * (m[0][0] * qd[0] * qd[0] + 2.0 * m[0][1] * qd[0] * qd[1] + m[1][1] * qd[1] * qd[1])
            + 0.5 * (i1 * qd[0] * qd[0] + i2 * qd[1] * qd[1])
    })
    .potential(move |q| {
        let (s1, s12) = (q[0].sin(), (q[0] + q[1]).sin());
        m1 * g * l / 2.0 * s1 + m2 * g * (l * s1 + l / 2.0 * s12)
    })
}

/// The uncorrected erratum 1 (`docs/errata.md`): the printed T2 of Example 6.8 (actuator term
/// `I2(act) θ̈1`) does not match the generated code, while the corrected one does (checked
/// above), i.e. the erratum is real and the test can tell the difference.
#[test]
fn example_6_8_printed_t2_erratum_1_is_detected() {
    let (l, m1, m2, g, i1, i2) = (0.7, 2.0, 1.5, 9.81, 0.05, 0.02);
    let arm = NikuArm {
        l,
        m1,
        m2,
        g,
        i1,
        i2,
    };
    let (q, qd, qdd): ([f64; 2], _, _) = ([0.3, -0.5], [0.1, 0.2], [1.0, -1.0]);
    let ll = l * l;
    let (c2, s2, c12) = (q[1].cos(), q[1].sin(), (q[0] + q[1]).cos());
    let without_actuator = (m2 * ll / 3.0 + m2 * ll * c2 / 2.0) * qdd[0]
        + m2 * ll * qdd[1] / 3.0
        + m2 * ll * s2 * qd[0] * qd[0] / 2.0
        + m2 * g * l * c12 / 2.0;
    let printed = without_actuator + i2 * qdd[0];
    let corrected = without_actuator + i2 * qdd[1];
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    assert!((tau[1] - corrected).abs() <= TOLERANCE * corrected.abs());
    // Differs by I2(act) (θ̈1 − θ̈2) = 0.04.
    assert!((tau[1] - printed).abs() > 0.03);
}
