//! The algorithms on kinematic trees built by hand, checked against values found another way:
//! the same links as separate serial chains, γ and b folded into the antecedent's own row, the
//! kinetic energy from the links' velocities by differences of their poses, `g = ∂P/∂q`,
//! `Ṁ = C + Cᵀ` and the Jacobian by central differences.

use dynamics_codegen::algo::{
    coriolis_matrix, crba, crba_derivative, gravity_torques, jacobian_in_base, kinematics,
    kinetic_energy, potential_energy, projected_torques, rnea, Chain, JointKind, RobotScalars, V3,
};
use dynamics_codegen::model::{Branch, Convention, Joint, Link, Robot, Value};

/// One joint of a hand-built robot: its antecedent (`Some` makes it a tree joint), kind, γ, b
/// and a seed its geometry and link follow from.
#[derive(Clone, Copy)]
pub(crate) struct Spec {
    pub parent: Option<usize>,
    pub kind: JointKind,
    pub gamma: f64,
    pub b: f64,
    pub seed: f64,
}

pub(crate) const R: JointKind = JointKind::Revolute;
pub(crate) const P: JointKind = JointKind::Prismatic;

/// A tree joint.
pub(crate) fn at(parent: Option<usize>, kind: JointKind, gamma: f64, b: f64, seed: f64) -> Spec {
    Spec {
        parent,
        kind,
        gamma,
        b,
        seed,
    }
}

/// A modified-convention robot; `tree` gives every joint a [`Branch`], otherwise none.
pub(crate) fn robot(specs: &[Spec], tree: bool) -> Robot {
    let v = Value::from_f64;
    let joints = specs
        .iter()
        .map(|s| {
            let x = s.seed;
            let (theta, d) = match s.kind {
                JointKind::Revolute => (0.1 * x, 0.05 + 0.02 * x),
                JointKind::Prismatic => (0.4 - 0.1 * x, 0.1),
            };
            let link = Link {
                mass: v(1.0 + 0.3 * x),
                com: [v(-0.1 + 0.02 * x), v(0.03), v(0.05 - 0.01 * x)],
                inertia: [0.05, 0.04 + 0.01 * x, 0.03, 0.004, -0.002, 0.001 * x].map(v),
                ..Link::default()
            };
            let row = [theta, d, 0.3 - 0.05 * x, 0.7 - 0.45 * x].map(v);
            let mut joint = Joint::dh(s.kind, row, link);
            joint.branch = tree.then(|| Branch {
                parent: s.parent,
                gamma: v(s.gamma),
                b: v(s.b),
            });
            joint
        })
        .collect();
    Robot {
        name: "tree".into(),
        convention: Convention::Modified,
        gravity: [0.5, -1.0, -9.7].map(v),
        joints,
        base: dynamics_codegen::model::Pose::identity(),
        tool: None,
        tips: Vec::new(),
    }
}

/// A robot's literal values at a position.
pub(crate) struct At<'a>(pub &'a [f64]);

impl RobotScalars for At<'_> {
    type Scalar = f64;

    fn value(&self, v: &Value) -> f64 {
        v.eval(&|_| None).unwrap_or(f64::NAN)
    }

    fn sin_cos(&self, v: &Value) -> (f64, f64) {
        self.value(v).sin_cos()
    }

    fn joint_variable(&self, joint: usize) -> f64 {
        self.0[joint]
    }

    fn joint_sin_cos(&mut self, joint: usize, offset: &Value) -> (f64, f64) {
        (self.0[joint] + self.value(offset)).sin_cos()
    }
}

pub(crate) fn chain(robot: &Robot, q: &[f64]) -> Chain<f64> {
    At(q).chain(robot)
}

fn gravity(robot: &Robot) -> V3<f64> {
    At(&[]).gravity(robot)
}

/// Three trees: a branch off a middle link (with γ, b and a prismatic joint on it), a joint
/// with three children (one prismatic, one turned by γ), two branches off the base (the
/// second ending in a link symmetric about its joint, set by [`symmetric_last`]).
pub(crate) fn trees() -> Vec<Vec<Spec>> {
    vec![
        vec![
            at(None, R, 0.0, 0.0, 0.0),
            at(Some(0), R, 0.0, 0.0, 1.0),
            at(Some(1), R, 0.0, 0.0, 2.0),
            at(Some(1), R, 0.6, 0.12, 3.0),
            at(Some(3), P, -0.3, 0.05, 4.0),
        ],
        vec![
            at(None, R, 0.0, 0.0, 0.5),
            at(Some(0), R, 0.0, 0.0, 1.5),
            at(Some(0), P, 1.1, -0.2, 2.5),
            at(Some(0), R, -0.8, 0.0, 3.5),
            at(Some(3), R, 0.0, 0.07, 4.5),
        ],
        vec![
            at(None, R, 0.0, 0.0, 1.0),
            at(Some(0), P, 0.0, 0.0, 2.0),
            at(Some(1), R, 0.0, 0.0, 3.0),
            at(None, R, 0.0, 0.0, 4.0),
            at(Some(3), R, 0.4, 0.1, 5.0),
        ],
    ]
}

/// `robot` with its last link made symmetric about its (revolute) joint's axis.
pub(crate) fn symmetric_last(mut robot: Robot) -> Robot {
    let v = Value::from_f64;
    if let Some(last) = robot.joints.last_mut() {
        last.link.com = [v(0.0), v(0.0), v(0.04)];
        last.link.inertia = [0.02, 0.02, 0.01, 0.0, 0.0, 0.0].map(v);
    }
    robot
}

const Q: [f64; 5] = [0.3, -1.1, 0.25, 2.0, -0.6];
const QD: [f64; 5] = [0.8, -0.4, 1.3, -2.1, 0.5];
const QDD: [f64; 5] = [-1.2, 0.6, 0.2, 1.7, -0.9];

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol * (1.0 + b.abs()), "{what}: {a} vs {b}");
}

fn each_close(a: &[f64], b: &[f64], tol: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        close(*x, *y, tol, &format!("{what} [{k}]"));
    }
}

/// `∂M/∂q_k` by central differences.
fn mass_derivative(robot: &Robot, q: &[f64], k: usize) -> Vec<Vec<f64>> {
    let h = 1e-6;
    let (mut p, mut m) = (q.to_vec(), q.to_vec());
    p[k] += h;
    m[k] -= h;
    let (mp, mm) = (crba(&chain(robot, &p)), crba(&chain(robot, &m)));
    let n = q.len();
    (0..n)
        .map(|i| (0..n).map(|j| (mp[i][j] - mm[i][j]) / (2.0 * h)).collect())
        .collect()
}

/// The kinetic energy link by link: each link's centre of mass velocity and angular velocity
/// from central differences of its pose along `q + t q̇`.
fn kinetic_by_poses(robot: &Robot, q: &[f64], qd: &[f64]) -> f64 {
    let h = 1e-6;
    let poses = |t: f64| {
        let q: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a + t * b).collect();
        kinematics(&mut At(&q), robot).links
    };
    let (plus, minus, now) = (poses(h), poses(-h), poses(0.0));
    let mut total = 0.0;
    for (l, joint) in robot.joints.iter().enumerate() {
        let link = &joint.link;
        let val = |v: &Value| v.eval(&|_| None).unwrap_or(f64::NAN);
        let c = link.com.each_ref().map(val);
        let [xx, yy, zz, xy, xz, yz] = link.inertia.each_ref().map(val);
        let inertia = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
        let point = |f: &dynamics_codegen::algo::Frame<f64>| {
            let r = &f.rotation.m;
            let p = f.position;
            [
                r[0][0] * c[0] + r[0][1] * c[1] + r[0][2] * c[2] + p.x,
                r[1][0] * c[0] + r[1][1] * c[1] + r[1][2] * c[2] + p.y,
                r[2][0] * c[0] + r[2][1] * c[1] + r[2][2] * c[2] + p.z,
            ]
        };
        let (a, b) = (point(&plus[l]), point(&minus[l]));
        let v: Vec<f64> = (0..3).map(|i| (a[i] - b[i]) / (2.0 * h)).collect();
        // [ω]× = Ṙ Rᵀ; ω in the link's axes is Rᵀ ω.
        let r = &now[l].rotation.m;
        let rdot =
            |i: usize, j: usize| (plus[l].rotation.m[i][j] - minus[l].rotation.m[i][j]) / (2.0 * h);
        let skew = |i: usize, j: usize| (0..3).map(|k| rdot(i, k) * r[j][k]).sum::<f64>();
        let w = [skew(2, 1), skew(0, 2), skew(1, 0)];
        let w_local: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|k| r[k][i] * w[k]).sum())
            .collect();
        let iw: f64 = (0..3)
            .map(|i| {
                (0..3)
                    .map(|k| w_local[i] * inertia[i][k] * w_local[k])
                    .sum::<f64>()
            })
            .sum();
        let mass = val(&link.mass);
        total += 0.5 * mass * v.iter().map(|x| x * x).sum::<f64>() + 0.5 * iw;
    }
    total
}

/// M's columns are Newton-Euler's with `q̇ = 0`, `q̈ = e_j` and no gravity; its entries are
/// exact zeros where neither joint is the other's ancestor, and not zero elsewhere.
#[allow(clippy::needless_range_loop)]
fn check_mass(c: &Chain<f64>, m: &[Vec<f64>]) {
    let n = m.len();
    let zeros = vec![0.0; n];
    for j in 0..n {
        let mut e = zeros.clone();
        e[j] = 1.0;
        let column = rnea(c, &zeros, &e, V3::zero(0.0));
        let from_m: Vec<f64> = (0..n).map(|i| m[i][j]).collect();
        each_close(&column, &from_m, 1e-12, "Newton-Euler column of M");
        for i in 0..n {
            if !c.supports(i, j) && !c.supports(j, i) {
                assert_eq!(m[i][j].to_bits(), 0, "M({i}, {j}) off the ancestry");
            } else {
                assert!(m[i][j] != 0.0, "M({i}, {j}) on the ancestry");
            }
        }
    }
}

/// The identities every robot's algorithms satisfy, checked on `robot` at one state.
fn check_identities(robot: &Robot) {
    let n = robot.dof();
    let (q, qd, qdd) = (&Q[..n], &QD[..n], &QDD[..n]);
    let g = gravity(robot);
    let zeros = vec![0.0; n];
    let none = V3::zero(0.0);
    let c = chain(robot, q);
    let m = crba(&c);
    check_mass(&c, &m);
    let m_qd: Vec<f64> = (0..n)
        .map(|i| (0..n).map(|j| m[i][j] * qd[j]).sum())
        .collect();
    let twice: f64 = qd.iter().zip(&m_qd).map(|(a, b)| a * b).sum();
    close(
        kinetic_energy(&c, qd, 0.0),
        0.5 * twice,
        1e-12,
        "K = ½ q̇ᵀ M q̇",
    );
    close(
        kinetic_by_poses(robot, q, qd),
        0.5 * twice,
        1e-7,
        "K link by link",
    );
    let h = 1e-6;
    let dp: Vec<f64> = (0..n)
        .map(|k| {
            let (mut a, mut b) = (q.to_vec(), q.to_vec());
            a[k] += h;
            b[k] -= h;
            let pe = |q: &[f64]| potential_energy(&chain(robot, q), g);
            (pe(&a) - pe(&b)) / (2.0 * h)
        })
        .collect();
    each_close(&gravity_torques(&c, g), &dp, 1e-7, "g = ∂P/∂q");
    each_close(
        &rnea(&c, &zeros, &zeros, g),
        &dp,
        1e-7,
        "Newton-Euler at rest",
    );
    let coriolis = coriolis_matrix(&c, qd).expect("no sums of angles in a tree");
    let dm: Vec<Vec<Vec<f64>>> = (0..n).map(|k| mass_derivative(robot, q, k)).collect();
    for i in 0..n {
        for j in 0..n {
            let m_dot: f64 = (0..n).map(|k| dm[k][i][j] * qd[k]).sum();
            let sum = coriolis[i][j] + coriolis[j][i];
            close(sum, m_dot, 1e-7, &format!("Ṁ = C + Cᵀ ({i}, {j})"));
        }
    }
    for (k, dm_k) in dm.iter().enumerate() {
        if let Some(analytic) = crba_derivative(&c, k) {
            each_close(&analytic.concat(), &dm_k.concat(), 1e-7, "∂M/∂q_k");
        }
    }
    let c_qd: Vec<f64> = (0..n)
        .map(|i| (0..n).map(|j| coriolis[i][j] * qd[j]).sum())
        .collect();
    each_close(&rnea(&c, qd, &zeros, none), &c_qd, 1e-12, "C q̇");
    let tau = rnea(&c, qd, qdd, g);
    let sum: Vec<f64> = (0..n)
        .map(|i| (0..n).map(|j| m[i][j] * qdd[j]).sum::<f64>() + c_qd[i] + dp[i])
        .collect();
    each_close(&tau, &sum, 1e-7, "τ = M q̈ + C q̇ + g");
    each_close(
        &projected_torques(&c, None, qd, qdd, g),
        &tau,
        1e-12,
        "projection",
    );
    // Regrouped onto the antecedents, bodies moved before the twist: the same dynamics.
    for before in [false, true] {
        let other = c.clone().moving_before_twist(before).regrouped();
        each_close(&crba(&other).concat(), &m.concat(), 1e-12, "regrouped M");
        each_close(&rnea(&other, qd, qdd, g), &tau, 1e-12, "regrouped τ");
        let ke = kinetic_energy(&other, qd, 0.0);
        close(ke, kinetic_energy(&c, qd, 0.0), 1e-12, "regrouped K");
        let p = potential_energy(&other, g);
        close(p, potential_energy(&c, g), 1e-12, "regrouped P");
    }
}

#[test]
fn identities_on_trees() {
    for specs in trees() {
        check_identities(&robot(&specs, true));
        check_identities(&symmetric_last(robot(&specs, true)));
    }
}

/// Two chains hung off the base are the two serial chains evaluated apart, block by block,
/// and nothing couples them.
#[test]
fn two_branches_off_the_base_are_two_chains() {
    let specs = &trees()[2];
    let tree = robot(specs, true);
    let first = robot(&specs[..3], false);
    let mut second_specs = specs[3..].to_vec();
    second_specs[1].gamma = 0.0;
    second_specs[1].b = 0.0;
    let second = robot(&second_specs, false);
    let mut tree = tree;
    tree.joints[4].branch = Some(Branch {
        parent: Some(3),
        gamma: Value::zero(),
        b: Value::zero(),
    });
    let g = gravity(&tree);
    let (c, a, b) = (
        chain(&tree, &Q),
        chain(&first, &Q[..3]),
        chain(&second, &Q[3..]),
    );
    let (m, ma, mb) = (crba(&c), crba(&a), crba(&b));
    for i in 0..5 {
        for j in 0..5 {
            let expected = match (i < 3, j < 3) {
                (true, true) => ma[i][j],
                (false, false) => mb[i - 3][j - 3],
                _ => 0.0,
            };
            close(m[i][j], expected, 1e-14, &format!("M({i}, {j})"));
        }
    }
    let tau = rnea(&c, &QD, &QDD, g);
    let apart = [
        rnea(&a, &QD[..3], &QDD[..3], g),
        rnea(&b, &QD[3..], &QDD[3..], g),
    ]
    .concat();
    each_close(&tau, &apart, 1e-13, "τ");
    let k = kinetic_energy(&a, &QD[..3], 0.0) + kinetic_energy(&b, &QD[3..], 0.0);
    close(kinetic_energy(&c, &QD, 0.0), k, 1e-13, "K");
    let p = potential_energy(&a, g) + potential_energy(&b, g);
    close(potential_energy(&c, g), p, 1e-13, "P");
    let cc = coriolis_matrix(&c, &QD).expect("no runs");
    let (ca, cb) = (
        coriolis_matrix(&a, &QD[..3]).expect("no runs"),
        coriolis_matrix(&b, &QD[3..]).expect("no runs"),
    );
    for i in 0..5 {
        for j in 0..5 {
            let expected = match (i < 3, j < 3) {
                (true, true) => ca[i][j],
                (false, false) => cb[i - 3][j - 3],
                _ => 0.0,
            };
            close(cc[i][j], expected, 1e-13, &format!("C({i}, {j})"));
        }
    }
}

/// γ and b before a joint's row are the antecedent's θ and d grown by them, its link's
/// parameters given in the frame so moved: `c' = Rotz(γ)ᵀ (c − b z)`, `I' = Rotz(γ)ᵀ I Rotz(γ)`.
#[test]
fn gamma_and_b_fold_into_the_antecedent() {
    let (gamma, b) = (0.7, -0.15);
    for kind in [R, P] {
        let specs = [
            at(None, R, 0.0, 0.0, 0.0),
            at(Some(0), kind, 0.0, 0.0, 1.0),
            at(Some(1), R, gamma, b, 2.0),
            at(Some(2), P, 0.0, 0.0, 3.0),
        ];
        let with_branch = robot(&specs, true);
        let mut folded = robot(&specs, false);
        let v = Value::from_f64;
        let val = |x: &Value| x.eval(&|_| None).unwrap_or(f64::NAN);
        let moved = &mut folded.joints[1];
        moved.theta = v(val(&moved.theta) + gamma);
        moved.d = v(val(&moved.d) + b);
        let (s, c) = gamma.sin_cos();
        let [x, y, z] = moved.link.com.each_ref().map(val);
        let z = z - b;
        moved.link.com = [c * x + s * y, -s * x + c * y, z].map(v);
        let [xx, yy, zz, xy, xz, yz] = moved.link.inertia.each_ref().map(val);
        let i = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
        let r = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
        // Rᵀ I R.
        let e = |a: usize, bb: usize| -> f64 {
            (0..3)
                .map(|k| (0..3).map(|l| r[k][a] * i[k][l] * r[l][bb]).sum::<f64>())
                .sum()
        };
        moved.link.inertia = [e(0, 0), e(1, 1), e(2, 2), e(0, 1), e(0, 2), e(1, 2)].map(v);
        let g = gravity(&folded);
        let (q, qd, qdd) = (&Q[..4], &QD[..4], &QDD[..4]);
        let (ct, cf) = (chain(&with_branch, q), chain(&folded, q));
        each_close(&crba(&ct).concat(), &crba(&cf).concat(), 1e-13, "M");
        each_close(&rnea(&ct, qd, qdd, g), &rnea(&cf, qd, qdd, g), 1e-13, "τ");
        let (pt, pf) = (potential_energy(&ct, g), potential_energy(&cf, g));
        close(pt, pf, 1e-13, "P");
        let hand = |r: &Robot| kinematics(&mut At(q), r).hand.rows().concat();
        each_close(&hand(&with_branch), &hand(&folded), 1e-13, "hand");
    }
}

/// The hand is the last joint's link: its Jacobian is the derivative of its pose along the
/// ancestors' joints, and zero in the others' columns.
#[test]
fn jacobian_of_the_last_link() {
    for specs in trees() {
        let robot = robot(&specs, true);
        let n = robot.dof();
        let q = &Q[..n];
        let k = kinematics(&mut At(q), &robot);
        let j = jacobian_in_base(&k);
        let c = chain(&robot, q);
        let h = 1e-6;
        for col in 0..n {
            let moves = c.supports(col, n - 1);
            let (mut a, mut b) = (q.to_vec(), q.to_vec());
            a[col] += h;
            b[col] -= h;
            let (pa, pb) = (
                kinematics(&mut At(&a), &robot).hand.position,
                kinematics(&mut At(&b), &robot).hand.position,
            );
            let fd = [pa.x - pb.x, pa.y - pb.y, pa.z - pb.z].map(|d| d / (2.0 * h));
            for row in 0..3 {
                close(j[row][col], fd[row], 1e-7, &format!("J({row}, {col})"));
            }
            if !moves {
                assert!((0..6).all(|r| j[r][col] == 0.0), "column {col}");
            }
        }
    }
}
