//! The worked examples of Niku, *Introduction to Robotics*, ch. 6 (Examples 6.1–6.5 and 6.8),
//! each derived from a D-H table with `#[derive(Dynamics)]` and checked against the book's
//! PRINTED equations of motion, typed in below by hand (corrected per `ERRATA.md` where it
//! says so), at many random states with random parameters.
//!
//! The expected values come only from the book's formulas, never from the code under test. What
//! is checked, where the book prints it:
//!
//! * `inverse_dynamics` against the printed scalar equations T/F;
//! * `mass_matrix`, `coriolis_torques` (the velocity terms) and `gravity_torques` against the
//!   printed matrix form, and τ = M q̈ + (velocity terms) + (gravity terms) of that matrix form
//!   against `inverse_dynamics` (which also cross-checks the book's two forms with each other);
//! * `coriolis_matrix`: C q̇ = `coriolis_torques`, and C + Cᵀ = Ṁ with Ṁ the time derivative of
//!   the printed M (differentiated by hand, noted at each example); for Example 6.8 also
//!   C_ij = Σ_k D_ijk q̇_k with the printed D_ijk;
//! * `kinetic_energy` against the printed K, `potential_energy` against the printed P up to the
//!   constant datum offset (compared as differences P(q_a) − P(q_b));
//! * the generated code's own identities: `bias_torques` = C q̇ + g, τ = M q̈ + C q̇ + g.
//!
//! Errors are relative, max|got − want| / max|want| (absolute where the expected value is
//! exactly zero), and must stay below 1e-12. Run with `-- --nocapture` to see the worst error per
//! quantity and example.

use dynamics_runtime::Dynamics;

/// Random states (and random parameter sets) per example.
const STATES: usize = 200;
/// Largest accepted relative error.
const TOLERANCE: f64 = 1e-12;

type Vector<const N: usize> = [f64; N];
type Matrix<const N: usize> = [[f64; N]; N];
type Christoffel<const N: usize> = [[[f64; N]; N]; N];
type TauFn<const N: usize> = Box<dyn Fn(&Vector<N>, &Vector<N>, &Vector<N>) -> Vector<N>>;
type StateFn<const N: usize, O> = Box<dyn Fn(&Vector<N>, &Vector<N>) -> O>;
type ConfigFn<const N: usize, O> = Box<dyn Fn(&Vector<N>) -> O>;

/// xorshift64*: a small deterministic generator, so every run sees the same states.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `[lo, hi)`.
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

#[derive(Clone, Copy)]
enum Joint {
    Revolute,
    Prismatic,
}

/// The book's formulas for one parameter set. Only `tau` is required; the rest is checked where
/// the book prints it.
struct Book<const N: usize> {
    /// The printed scalar equations T_i / F_i.
    tau: TauFn<N>,
    /// Matrix form: the inertia matrix.
    mass: Option<ConfigFn<N, Matrix<N>>>,
    /// Matrix form: the centripetal and Coriolis terms.
    velocity: Option<StateFn<N, Vector<N>>>,
    /// Matrix form: the gravity (and spring) terms.
    gravity: Option<ConfigFn<N, Vector<N>>>,
    /// dM/dt of the printed M, differentiated by hand.
    mass_dot: Option<StateFn<N, Matrix<N>>>,
    /// The printed D_ijk (Example 6.8), `[i][j][k]`.
    christoffel: Option<ConfigFn<N, Christoffel<N>>>,
    /// The printed kinetic energy.
    kinetic: Option<StateFn<N, f64>>,
    /// The printed potential energy (any datum).
    potential: Option<ConfigFn<N, f64>>,
}

impl<const N: usize> Book<N> {
    fn new(tau: impl Fn(&Vector<N>, &Vector<N>, &Vector<N>) -> Vector<N> + 'static) -> Self {
        Book {
            tau: Box::new(tau),
            mass: None,
            velocity: None,
            gravity: None,
            mass_dot: None,
            christoffel: None,
            kinetic: None,
            potential: None,
        }
    }

    fn mass(mut self, f: impl Fn(&Vector<N>) -> Matrix<N> + 'static) -> Self {
        self.mass = Some(Box::new(f));
        self
    }

    fn velocity(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> Vector<N> + 'static) -> Self {
        self.velocity = Some(Box::new(f));
        self
    }

    fn gravity(mut self, f: impl Fn(&Vector<N>) -> Vector<N> + 'static) -> Self {
        self.gravity = Some(Box::new(f));
        self
    }

    fn mass_dot(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> Matrix<N> + 'static) -> Self {
        self.mass_dot = Some(Box::new(f));
        self
    }

    fn christoffel(mut self, f: impl Fn(&Vector<N>) -> Christoffel<N> + 'static) -> Self {
        self.christoffel = Some(Box::new(f));
        self
    }

    fn kinetic(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> f64 + 'static) -> Self {
        self.kinetic = Some(Box::new(f));
        self
    }

    fn potential(mut self, f: impl Fn(&Vector<N>) -> f64 + 'static) -> Self {
        self.potential = Some(Box::new(f));
        self
    }
}

/// max|got − want| / scale, with scale = max|want| (1 where `want` is exactly zero).
fn relative_error(got: &[f64], want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    scaled_error(got, want, if scale > 0.0 { scale } else { 1.0 })
}

fn scaled_error(got: &[f64], want: &[f64], scale: f64) -> f64 {
    assert_eq!(got.len(), want.len());
    got.iter()
        .zip(want)
        .map(|(a, b)| {
            if a.is_finite() {
                (a - b).abs() / scale
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max)
}

fn flat<const N: usize>(m: &Matrix<N>) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

fn mat_vec<const N: usize>(m: &Matrix<N>, v: &Vector<N>) -> Vector<N> {
    core::array::from_fn(|i| (0..N).map(|j| m[i][j] * v[j]).sum())
}

fn add<const N: usize>(a: &Vector<N>, b: &Vector<N>) -> Vector<N> {
    core::array::from_fn(|i| a[i] + b[i])
}

/// 2×2 matrix times vector, for the book's centripetal/Coriolis matrices in (6.5)–(6.16).
fn mv2(m: [[f64; 2]; 2], v: [f64; 2]) -> [f64; 2] {
    [
        m[0][0] * v[0] + m[0][1] * v[1],
        m[1][0] * v[0] + m[1][1] * v[1],
    ]
}

/// The worst error seen per checked quantity.
struct Worst {
    example: &'static str,
    rows: Vec<(&'static str, f64)>,
}

impl Worst {
    fn record(&mut self, what: &'static str, err: f64, got: &[f64], want: &[f64], state: &str) {
        assert!(
            err <= TOLERANCE,
            "Example {}: {what}: relative error {err:.3e} > {TOLERANCE:e}\n{state}\n  got  {got:?}\n  want {want:?}",
            self.example,
        );
        match self.rows.iter_mut().find(|(w, _)| *w == what) {
            Some((_, e)) => *e = e.max(err),
            None => self.rows.push((what, err)),
        }
    }
}

/// Draws `STATES` parameter sets (through `sample`) and states, and checks every formula the
/// example's [`Book`] provides against the generated code. Returns the worst error overall.
fn check<R: Dynamics<N>, const N: usize>(
    example: &'static str,
    seed: u64,
    joints: [Joint; N],
    mut sample: impl FnMut(&mut Rng) -> (R, Book<N>),
) -> f64 {
    let mut rng = Rng::new(seed);
    let mut worst = Worst {
        example,
        rows: Vec::new(),
    };
    for state in 0..STATES {
        let (robot, book) = sample(&mut rng);
        let mut config = || -> Vector<N> {
            core::array::from_fn(|i| match joints[i] {
                Joint::Revolute => rng.range(-std::f64::consts::PI, std::f64::consts::PI),
                Joint::Prismatic => rng.range(-1.0, 2.0),
            })
        };
        let q = config();
        let q_b = config();
        let qd: Vector<N> = core::array::from_fn(|_| rng.range(-3.0, 3.0));
        let qdd: Vector<N> = core::array::from_fn(|_| rng.range(-5.0, 5.0));
        let at = format!("state #{state}: q = {q:?}, qd = {qd:?}, qdd = {qdd:?}, q_b = {q_b:?}");
        let mut vector = |what, got: &[f64], want: &[f64]| {
            worst.record(what, relative_error(got, want), got, want, &at);
        };

        let tau = robot.inverse_dynamics(&q, &qd, &qdd);
        vector("tau (printed T/F)", &tau, &(book.tau)(&q, &qd, &qdd));

        let m = robot.mass_matrix(&q);
        let c = robot.coriolis_matrix(&q, &qd);
        let cqd = robot.coriolis_torques(&q, &qd);
        let g = robot.gravity_torques(&q);
        if let Some(f) = &book.mass {
            vector("M (matrix form)", &flat(&m), &flat(&f(&q)));
        }
        if let Some(f) = &book.velocity {
            vector("C qd (velocity terms)", &cqd, &f(&q, &qd));
        }
        if let Some(f) = &book.gravity {
            vector("g (gravity terms)", &g, &f(&q));
        }
        if let (Some(mf), Some(vf), Some(gf)) = (&book.mass, &book.velocity, &book.gravity) {
            let want = add(&add(&mat_vec(&mf(&q), &qdd), &vf(&q, &qd)), &gf(&q));
            vector("tau (matrix form)", &tau, &want);
        }
        if let Some(f) = &book.mass_dot {
            let got: Matrix<N> =
                core::array::from_fn(|i| core::array::from_fn(|j| c[i][j] + c[j][i]));
            vector("C + C^T = dM/dt", &flat(&got), &flat(&f(&q, &qd)));
        }
        if let Some(f) = &book.christoffel {
            let d = f(&q);
            let want: Matrix<N> = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..N).map(|k| d[i][j][k] * qd[k]).sum())
            });
            vector("C_ij = sum_k D_ijk qd_k", &flat(&c), &flat(&want));
        }
        if let Some(f) = &book.kinetic {
            vector("K", &[robot.kinetic_energy(&q, &qd)], &[f(&q, &qd)]);
        }

        // The generated code's own identities.
        vector("C qd = coriolis_torques", &mat_vec(&c, &qd), &cqd);
        let want = add(&cqd, &g);
        vector("bias = C qd + g", &robot.bias_torques(&q, &qd), &want);
        vector(
            "tau = M qdd + C qd + g",
            &tau,
            &add(&mat_vec(&m, &qdd), &want),
        );

        if let Some(f) = &book.potential {
            // Only differences: the book's datum is not the generated code's.
            let (pa, pb) = (f(&q), f(&q_b));
            let got = robot.potential_energy(&q) - robot.potential_energy(&q_b);
            let want = pa - pb;
            let scale = want.abs().max(pa.abs()).max(pb.abs());
            let err = scaled_error(&[got], &[want], if scale > 0.0 { scale } else { 1.0 });
            worst.record("P(q) - P(q_b)", err, &[got], &[want], &at);
        }
    }
    // One print, so that the reports of tests running in parallel do not interleave.
    let mut report =
        format!("Example {example}: {STATES} random states, worst relative error per quantity:");
    for (what, err) in &worst.rows {
        report += &format!("\n  {what:<26} {err:.2e}");
    }
    println!("{report}");
    worst.rows.iter().fold(0.0, |m, (_, e)| m.max(*e))
}

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
/// ERRATA #3 concerns only the intermediate d/dt(∂L/∂θ̇1) line; the final T1 and (6.6) are used
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

/// As in `/work/shared/reference/README.md` ("Example 6.5 (polar arm) in D-H form"): z1 points
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
/// Ṁ: d/dt (m2 r²) = 2 m2 r ṙ. ERRATA #2 concerns only the intermediate d/dt(∂L/∂θ̇) line;
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

/// Example 6.8: the printed final T1 and T2, **T2 corrected per ERRATA #1** (its actuator term
/// is I2(act) θ̈2, printed I2(act) θ̈1); M = [D_ij] + diag(I1(act), I2(act)) with the printed
/// D11, D12 = D21, D22 (eqs. 6.42/6.46); the printed D_ijk as Christoffel symbols,
/// C_ij = Σ_k D_ijk q̇_k, and the velocity terms Σ_jk D_ijk q̇_j q̇_k of (6.46); the printed D1, D2.
/// K = ½ Σ D_ij q̇_i q̇_j + ½ Σ I_i(act) q̇_i² (6.38, 6.39 with 6.43); P from (6.10) with
/// l1 = l2 = l (the book: "the same as Eqs. (6.11) and (6.12)"). Ṁ: d/dt (m2 l² C2) =
/// −m2 l² S2 θ̇2.
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
        let book = Book::new(move |q, qd, qdd| {
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
                    + i2 * t2dd, // ERRATA #1: printed `I2(act) θ̈1`
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
            0.5 * (m[0][0] * qd[0] * qd[0]
                + 2.0 * m[0][1] * qd[0] * qd[1]
                + m[1][1] * qd[1] * qd[1])
                + 0.5 * (i1 * qd[0] * qd[0] + i2 * qd[1] * qd[1])
        })
        .potential(move |q| {
            let (s1, s12) = (q[0].sin(), (q[0] + q[1]).sin());
            m1 * g * l / 2.0 * s1 + m2 * g * (l * s1 + l / 2.0 * s12)
        });
        (
            NikuArm {
                l,
                m1,
                m2,
                g,
                i1,
                i2,
            },
            book,
        )
    });
    assert!(worst <= TOLERANCE);
}

/// The uncorrected ERRATA #1: the printed T2 of Example 6.8 (actuator term `I2(act) θ̈1`) does
/// not match the generated code, while the corrected one does (checked above), i.e. the
/// erratum is real and the test can tell the difference.
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
