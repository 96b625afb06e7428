//! The harness of the book's worked examples (`tests/tests/niku_*_examples.rs`): a [`Book`]
//! holds the formulas the book prints for one parameter set, and [`check`] compares the
//! generated code with them at random states with random parameters.
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
use dynamics_test_support::{error_over, relative_error, Rng};

/// Random states (and random parameter sets) per example.
pub const STATES: usize = 200;
/// Largest accepted relative error.
pub const TOLERANCE: f64 = 1e-12;

pub type Vector<const N: usize> = [f64; N];
pub type Matrix<const N: usize> = [[f64; N]; N];
pub type Christoffel<const N: usize> = [[[f64; N]; N]; N];
pub type TauFn<const N: usize> = Box<dyn Fn(&Vector<N>, &Vector<N>, &Vector<N>) -> Vector<N>>;
pub type StateFn<const N: usize, O> = Box<dyn Fn(&Vector<N>, &Vector<N>) -> O>;
pub type ConfigFn<const N: usize, O> = Box<dyn Fn(&Vector<N>) -> O>;

#[derive(Clone, Copy)]
pub enum Joint {
    Revolute,
    Prismatic,
}

/// The book's formulas for one parameter set. Only `tau` is required; the rest is checked where
/// the book prints it.
pub struct Book<const N: usize> {
    /// The printed scalar equations T_i / F_i.
    pub tau: TauFn<N>,
    /// Matrix form: the inertia matrix.
    pub mass: Option<ConfigFn<N, Matrix<N>>>,
    /// Matrix form: the centripetal and Coriolis terms.
    pub velocity: Option<StateFn<N, Vector<N>>>,
    /// Matrix form: the gravity (and spring) terms.
    pub gravity: Option<ConfigFn<N, Vector<N>>>,
    /// dM/dt of the printed M, differentiated by hand.
    pub mass_dot: Option<StateFn<N, Matrix<N>>>,
    /// The printed D_ijk (Example 6.8), `[i][j][k]`.
    pub christoffel: Option<ConfigFn<N, Christoffel<N>>>,
    /// The printed kinetic energy.
    pub kinetic: Option<StateFn<N, f64>>,
    /// The printed potential energy (any datum).
    pub potential: Option<ConfigFn<N, f64>>,
}

impl<const N: usize> Book<N> {
    pub fn new(tau: impl Fn(&Vector<N>, &Vector<N>, &Vector<N>) -> Vector<N> + 'static) -> Self {
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

    pub fn mass(mut self, f: impl Fn(&Vector<N>) -> Matrix<N> + 'static) -> Self {
        self.mass = Some(Box::new(f));
        self
    }

    pub fn velocity(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> Vector<N> + 'static) -> Self {
        self.velocity = Some(Box::new(f));
        self
    }

    pub fn gravity(mut self, f: impl Fn(&Vector<N>) -> Vector<N> + 'static) -> Self {
        self.gravity = Some(Box::new(f));
        self
    }

    pub fn mass_dot(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> Matrix<N> + 'static) -> Self {
        self.mass_dot = Some(Box::new(f));
        self
    }

    pub fn christoffel(mut self, f: impl Fn(&Vector<N>) -> Christoffel<N> + 'static) -> Self {
        self.christoffel = Some(Box::new(f));
        self
    }

    pub fn kinetic(mut self, f: impl Fn(&Vector<N>, &Vector<N>) -> f64 + 'static) -> Self {
        self.kinetic = Some(Box::new(f));
        self
    }

    pub fn potential(mut self, f: impl Fn(&Vector<N>) -> f64 + 'static) -> Self {
        self.potential = Some(Box::new(f));
        self
    }
}

pub fn flat<const N: usize>(m: &Matrix<N>) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

pub fn mat_vec<const N: usize>(m: &Matrix<N>, v: &Vector<N>) -> Vector<N> {
    core::array::from_fn(|i| (0..N).map(|j| m[i][j] * v[j]).sum())
}

pub fn add<const N: usize>(a: &Vector<N>, b: &Vector<N>) -> Vector<N> {
    core::array::from_fn(|i| a[i] + b[i])
}

/// 2×2 matrix times vector, for the book's centripetal/Coriolis matrices in (6.5)–(6.16).
pub fn mv2(m: [[f64; 2]; 2], v: [f64; 2]) -> [f64; 2] {
    [
        m[0][0] * v[0] + m[0][1] * v[1],
        m[1][0] * v[0] + m[1][1] * v[1],
    ]
}

/// The worst error seen per checked quantity.
pub struct Worst {
    pub example: &'static str,
    pub rows: Vec<(&'static str, f64)>,
}

impl Worst {
    pub fn record(&mut self, what: &'static str, err: f64, got: &[f64], want: &[f64], state: &str) {
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
pub fn check<R: Dynamics<N>, const N: usize>(
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
            let err = error_over(&[got], &[want], if scale > 0.0 { scale } else { 1.0 });
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
