//! The worked examples of Niku, *Introduction to Robotics*, ch. 6, that are not robot arms
//! (Examples 6.1–6.3: a cart on a spring, a cart with a pendulum, a two-link arm of point
//! masses), each derived from a D-H table with `#[derive(Dynamics)]` and checked against the
//! book's PRINTED equations of motion, typed in below by hand (corrected where `docs/errata.md`
//! says so), at many random states with random parameters. The harness, and what it checks, is
//! `dynamics_tests::book`; the arms are in `niku_arm_examples.rs`.

use dynamics_runtime::Dynamics;
use dynamics_tests::book::{add, check, mv2, Book, Joint, TOLERANCE};

// ---------------------------------------------------------------------------------------------
// Example 6.1: a cart of mass m on a spring k, pushed by F.
// ---------------------------------------------------------------------------------------------

/// The cart slides along z0 (the book's x), horizontal: gravity is perpendicular to the motion.
/// `g` drops out of every equation; the derive still reads it, so no dead-code warning.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ   d   a   α
        [   0,  q,  0,  0 ],
    ],
    link(mass = m, spring = (k, 0)),
)]
struct Cart {
    m: f64,
    k: f64,
    g: f64,
}

/// Example 6.1: F = m ẍ + k x (printed, Lagrangian and Newtonian); K = ½ m ẋ², P = ½ k x².
/// The book prints no matrix form; its 1×1 terms are read off the printed F (M = m, no velocity
/// terms, g = k x). No errata.
#[test]
fn example_6_1_cart_with_spring() {
    let worst = check("6.1", 61, [Joint::Prismatic], |rng| {
        let (m, k, g) = (
            rng.range(0.5, 5.0),
            rng.range(0.5, 50.0),
            rng.range(1.0, 20.0),
        );
        let book = Book::new(move |q, _qd, qdd| [m * qdd[0] + k * q[0]])
            .mass(move |_q| [[m]])
            .velocity(|_q, _qd| [0.0])
            .gravity(move |q| [k * q[0]])
            .mass_dot(|_q, _qd| [[0.0]])
            .kinetic(move |_q, qd| 0.5 * m * qd[0] * qd[0])
            .potential(move |q| 0.5 * k * q[0] * q[0]);
        (Cart { m, k, g }, book)
    });
    assert!(worst <= TOLERANCE);
}

// ---------------------------------------------------------------------------------------------
// Example 6.2: cart (m1, spring k, along x) carrying a pendulum (point mass m2 at length l).
// ---------------------------------------------------------------------------------------------

/// Base frame: y0 up, z0 along the book's x (the cart's motion), x0 = y0 × z0 (out of the
/// plane, backwards). Row 1 (prismatic, d = x) turns the frame so that z1 is normal to the plane
/// of motion (x1 = up, y1 = −x_book). Row 2 rotates about z1; with θ2 = θ + 180° the pendulum
/// bob sits at l(cos θ2 x1 + sin θ2 y1) = (l sin θ along x_book, −l cos θ vertical) from the
/// cart, which is what the book's v_p = (ẋ + lθ̇ cos θ) i + lθ̇ sin θ j integrates to.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        //  θ             d   a   α
        [   90 deg,       q,  0,  -90 deg ],
        [   q + 180 deg,  0,  l,  0       ],
    ],
    link(mass = m1, spring = (k, 0)),
    link(mass = m2),
)]
struct CartPendulum {
    m1: f64,
    m2: f64,
    l: f64,
    k: f64,
    g: f64,
}

/// Example 6.2: the printed F and T before eq. (6.5) and the matrix form (6.5); the printed K and
/// P = ½ k x² + m2 g l (1 − cos θ) (datum at θ = 0, so P differs from the generated one by the
/// constant m2 g l). Ṁ: d/dt (m2 l cos θ) = −m2 l sin θ θ̇. No errata.
#[test]
fn example_6_2_cart_pendulum() {
    let worst = check("6.2", 62, [Joint::Prismatic, Joint::Revolute], |rng| {
        let (m1, m2) = (rng.range(0.5, 5.0), rng.range(0.5, 5.0));
        let (l, k, g) = (
            rng.range(0.2, 2.0),
            rng.range(0.5, 50.0),
            rng.range(1.0, 20.0),
        );
        let book = Book::new(move |q, qd, qdd| {
                let [x, th] = *q;
                let thd = qd[1];
                let [xdd, thdd] = *qdd;
                let (s, c) = th.sin_cos();
                [
                    // F = (m1 + m2) ẍ + m2 l cos θ θ̈ − m2 l sin θ θ̇² + k x
                    (m1 + m2) * xdd + m2 * l * c * thdd - m2 * l * s * thd * thd + k * x,
                    // T = m2 l² θ̈ + m2 l ẍ cos θ + m2 g l sin θ
                    m2 * l * l * thdd + m2 * l * xdd * c + m2 * g * l * s,
                ]
            })
            // (6.5)
            .mass(move |q| {
                let c = q[1].cos();
                [[m1 + m2, m2 * l * c], [m2 * l * c, m2 * l * l]]
            })
            .velocity(move |q, qd| {
                let s = q[1].sin();
                mv2(
                    [[0.0, -m2 * l * s], [0.0, 0.0]],
                    [qd[0] * qd[0], qd[1] * qd[1]],
                )
            })
            .gravity(move |q| [k * q[0], m2 * g * l * q[1].sin()])
            .mass_dot(move |q, qd| {
                let d = -m2 * l * q[1].sin() * qd[1];
                [[0.0, d], [d, 0.0]]
            })
            // K = ½ (m1 + m2) ẋ² + ½ m2 (l² θ̇² + 2 l θ̇ ẋ cos θ)
            .kinetic(move |q, qd| {
                let [xd, thd] = *qd;
                0.5 * (m1 + m2) * xd * xd
                    + 0.5 * m2 * (l * l * thd * thd + 2.0 * l * thd * xd * q[1].cos())
            })
            // P = ½ k x² + m2 g l (1 − cos θ)
            .potential(move |q| 0.5 * k * q[0] * q[0] + m2 * g * l * (1.0 - q[1].cos()));
        (CartPendulum { m1, m2, l, k, g }, book)
    });
    assert!(worst <= TOLERANCE);
}

// ---------------------------------------------------------------------------------------------
// Example 6.3: 2R arm with point masses m1, m2 at the link ends, angles from the downward
// vertical.
// ---------------------------------------------------------------------------------------------

/// x0 points down (the book's −y), y0 along the book's x: then the D-H positions
/// (l1 C1 + l2 C12, l1 S1 + l2 S12) are the book's (−y_B, x_B), and gravity is +x0.
#[derive(Dynamics)]
#[dynamics(
    gravity = [g, 0, 0],
    dh = [
        //  θ   d   a    α
        [   q,  0,  l1,  0 ],
        [   q,  0,  l2,  0 ],
    ],
    link(mass = m1),
    link(mass = m2),
)]
struct PointMassArm {
    l1: f64,
    l2: f64,
    m1: f64,
    m2: f64,
    g: f64,
}

/// Example 6.3: the printed T1, T2 and the matrix form (6.6); the printed K and
/// P = −(m1 + m2) g l1 C1 − m2 g l2 C12 (datum at o, the base origin). Ṁ:
/// d/dt (2 m2 l1 l2 C2) = −2 m2 l1 l2 S2 θ̇2, d/dt (m2 l1 l2 C2) = −m2 l1 l2 S2 θ̇2.
/// Erratum 3 of `docs/errata.md` concerns only the intermediate d/dt(∂L/∂θ̇1) line; the final T1 and (6.6) are used
/// as printed.
#[test]
fn example_6_3_point_mass_arm() {
    let worst = check("6.3", 63, [Joint::Revolute, Joint::Revolute], |rng| {
        let (l1, l2) = (rng.range(0.2, 2.0), rng.range(0.2, 2.0));
        let (m1, m2, g) = (
            rng.range(0.5, 5.0),
            rng.range(0.5, 5.0),
            rng.range(1.0, 20.0),
        );
        let book = Book::new(move |q, qd, qdd| {
                let (s1, c2, s2, s12) = (q[0].sin(), q[1].cos(), q[1].sin(), (q[0] + q[1]).sin());
                let [t1d, t2d] = *qd;
                let [t1dd, t2dd] = *qdd;
                [
                    ((m1 + m2) * l1 * l1 + m2 * l2 * l2 + 2.0 * m2 * l1 * l2 * c2) * t1dd
                        + (m2 * l2 * l2 + m2 * l1 * l2 * c2) * t2dd
                        - 2.0 * m2 * l1 * l2 * s2 * t1d * t2d
                        - m2 * l1 * l2 * s2 * t2d * t2d
                        + (m1 + m2) * g * l1 * s1
                        + m2 * g * l2 * s12,
                    (m2 * l2 * l2 + m2 * l1 * l2 * c2) * t1dd
                        + m2 * l2 * l2 * t2dd
                        + m2 * l1 * l2 * s2 * t1d * t1d
                        + m2 * g * l2 * s12,
                ]
            })
            // (6.6)
            .mass(move |q| {
                let c2 = q[1].cos();
                let m12 = m2 * l2 * l2 + m2 * l1 * l2 * c2;
                [
                    [
                        (m1 + m2) * l1 * l1 + m2 * l2 * l2 + 2.0 * m2 * l1 * l2 * c2,
                        m12,
                    ],
                    [m12, m2 * l2 * l2],
                ]
            })
            .velocity(move |q, qd| {
                let h = m2 * l1 * l2 * q[1].sin();
                let [t1d, t2d] = *qd;
                add(
                    &mv2([[0.0, -h], [h, 0.0]], [t1d * t1d, t2d * t2d]),
                    &mv2([[-h, -h], [0.0, 0.0]], [t1d * t2d, t2d * t1d]),
                )
            })
            .gravity(move |q| {
                let (s1, s12) = (q[0].sin(), (q[0] + q[1]).sin());
                [
                    (m1 + m2) * g * l1 * s1 + m2 * g * l2 * s12,
                    m2 * g * l2 * s12,
                ]
            })
            .mass_dot(move |q, qd| {
                let d = -m2 * l1 * l2 * q[1].sin() * qd[1];
                [[2.0 * d, d], [d, 0.0]]
            })
            // K = ½ (m1 + m2) l1² θ̇1² + ½ m2 l2² (θ̇1² + θ̇2² + 2 θ̇1 θ̇2) + m2 l1 l2 C2 (θ̇1² + θ̇1 θ̇2)
            .kinetic(move |q, qd| {
                let [t1d, t2d] = *qd;
                0.5 * (m1 + m2) * l1 * l1 * t1d * t1d
                    + 0.5 * m2 * l2 * l2 * (t1d * t1d + t2d * t2d + 2.0 * t1d * t2d)
                    + m2 * l1 * l2 * q[1].cos() * (t1d * t1d + t1d * t2d)
            })
            .potential(move |q| {
                -(m1 + m2) * g * l1 * q[0].cos() - m2 * g * l2 * (q[0] + q[1]).cos()
            });
        (PointMassArm { l1, l2, m1, m2, g }, book)
    });
    assert!(worst <= TOLERANCE);
}
