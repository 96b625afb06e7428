//! Mimic joints through the whole trace, against the same robot traced with every joint free
//! and projected by hand: at `q_full = S q + o`, `q̇_full = S q̇`, `q̈_full = S q̈`, the reduced
//! τ, g, C q̇, h and friction are `Sᵀ` of the full ones, M and C are `Sᵀ · S`, the energies and
//! the hand's pose equal, its Jacobian is `J S`, `M q̈ = τ − h − f` holds for the forward
//! dynamics, and the derivatives are `Sᵀ (∂τ/∂q) S`, `Sᵀ (∂τ/∂q̇) S` and `∂q̈/∂τ = M⁻¹`.

use crate::unit::algo::tree_tests::{at, robot, P, R};
use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::model::{Friction, Mimic, Robot, Spring, Value};
use dynamics_codegen::pipeline::{equations, State, Values};
use dynamics_codegen::trace::Equations;

const Q: [f64; 4] = [-0.4, 0.9, 0.15, 0.07];
const QD: [f64; 4] = [0.3, -1.2, 0.6, 0.9];
const QDD: [f64; 4] = [1.1, 0.2, -0.7, 0.4];
const TAU: [f64; 4] = [2.0, -1.5, 0.8, 0.3];

/// Joint `m` follows joint `j` with multiplier `k` and offset `o`.
pub(super) fn follow(robot: &mut Robot, m: usize, j: usize, k: f64, o: f64) {
    robot.joints[m].mimic = Some(Mimic {
        joint: j,
        multiplier: Value::from_f64(k),
        offset: Value::from_f64(o),
    });
}

/// The robot with friction, a spring and actuator inertia on its mimic joints, so that their
/// projection shows.
fn with_drives(mut robot: Robot) -> Robot {
    let v = Value::from_f64;
    for joint in robot.joints.iter_mut().filter(|j| j.mimic.is_some()) {
        joint.link.friction = Some(Friction {
            viscous: v(0.4),
            coulomb: v(0.2),
            offset: v(0.0),
            smoothing: Some(v(0.5)),
        });
        joint.link.spring = Some(Spring {
            stiffness: v(3.0),
            rest: v(0.1),
        });
        joint.link.actuator_inertia = v(0.02);
    }
    robot
}

fn close(a: &[f64], b: &[f64], tol: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= tol * (1.0 + y.abs()),
            "{what} [{k}]: {x} vs {y}"
        );
    }
}

/// S (joints × coordinates) and o of `robot`, from its mimic rules.
fn map(robot: &Robot) -> (Vec<Vec<f64>>, Vec<f64>) {
    let coordinates = robot.coordinates();
    let value = |v: &Value| v.eval(&|_| None).expect("a number");
    let mut s = vec![vec![0.0; coordinates.len()]; robot.dof()];
    let mut o = vec![0.0; robot.dof()];
    for (i, joint) in robot.joints.iter().enumerate() {
        let (followed, k) = match &joint.mimic {
            Some(m) => {
                o[i] = value(&m.offset);
                (m.joint, value(&m.multiplier))
            }
            None => (i, 1.0),
        };
        let c = coordinates
            .iter()
            .position(|&j| j == followed)
            .expect("a coordinate");
        s[i][c] = k;
    }
    (s, o)
}

fn times(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let columns = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..columns)
                .map(|j| row.iter().zip(b).map(|(x, r)| x * r[j]).sum())
                .collect()
        })
        .collect()
}

fn transposed(a: &[Vec<f64>]) -> Vec<Vec<f64>> {
    (0..a[0].len())
        .map(|j| a.iter().map(|r| r[j]).collect())
        .collect()
}

fn column(v: &[f64]) -> Vec<Vec<f64>> {
    v.iter().map(|&x| vec![x]).collect()
}

fn projected(s: &[Vec<f64>], v: &[f64]) -> Vec<f64> {
    times(&transposed(s), &column(v)).concat()
}

fn sandwiched(s: &[Vec<f64>], m: &[Vec<f64>]) -> Vec<f64> {
    times(&times(&transposed(s), m), s).concat()
}

/// `robot` (with mimic joints) against itself without them, projected.
fn check(robot: &Robot) {
    let families = FamilySet::default().with(Family::Derivatives);
    let mut free = robot.clone();
    free.joints.iter_mut().for_each(|j| j.mimic = None);
    let (s, o) = map(robot);
    let n = s[0].len();
    let (q, qd, qdd, tau) = (&Q[..n], &QD[..n], &QDD[..n], &TAU[..n]);
    let full = |x: &[f64], offset: bool| -> Vec<f64> {
        let sx = times(&s, &column(x)).concat();
        sx.iter()
            .zip(&o)
            .map(|(a, b)| a + if offset { *b } else { 0.0 })
            .collect()
    };
    let (eq, _) = equations(robot, families, None);
    let (eq_full, _) = equations(&free, families, None);
    assert_eq!((eq.dof, eq_full.dof), (n, robot.dof()));
    fn state<'a>(q: &'a [f64], qd: &'a [f64], qdd: &'a [f64]) -> State<'a> {
        State {
            fields: &[],
            q,
            qd,
            qdd,
            tau: &[],
        }
    }
    let (fq, fqd, fqdd) = (full(q, true), full(qd, false), full(qdd, false));
    let at = eq.evaluate(&State {
        tau,
        ..state(q, qd, qdd)
    });
    let at_full = eq_full.evaluate(&state(&fq, &fqd, &fqdd));
    for (what, reduced, whole) in vectors(&eq, &eq_full) {
        close(
            &at.vector(reduced),
            &projected(&s, &at_full.vector(whole)),
            1e-12,
            what,
        );
    }
    for (what, reduced, whole) in matrices(&eq, &eq_full) {
        let want = sandwiched(&s, &at_full.matrix(whole));
        close(&at.matrix(reduced).concat(), &want, 1e-12, what);
    }
    let energies = [eq.kinetic_energy, eq.potential_energy];
    let energies_full = [eq_full.kinetic_energy, eq_full.potential_energy];
    close(
        &at.vector(&energies),
        &at_full.vector(&energies_full),
        1e-12,
        "energies",
    );
    let pose = at.matrix(&eq.kinematics.hand_pose).concat();
    close(
        &pose,
        &at_full.matrix(&eq_full.kinematics.hand_pose).concat(),
        1e-12,
        "pose",
    );
    let jacobian = times(&at_full.matrix(&eq_full.kinematics.jacobian_in_base), &s);
    let traced = at.matrix(&eq.kinematics.jacobian_in_base);
    close(&traced.concat(), &jacobian.concat(), 1e-12, "J S");
    forward(&eq, &at, tau);
    derivatives(&eq, &eq_full, &at, &at_full, &s);
}

type Vectors<'a> = [(
    &'a str,
    &'a [dynamics_codegen::symbolic::NodeId],
    &'a [dynamics_codegen::symbolic::NodeId],
); 6];

fn vectors<'a>(eq: &'a Equations, full: &'a Equations) -> Vectors<'a> {
    [
        ("τ", &eq.tau, &full.tau),
        ("g", &eq.gravity, &full.gravity),
        ("C q̇", &eq.coriolis_torques, &full.coriolis_torques),
        ("h", &eq.bias, &full.bias),
        ("friction", &eq.friction, &full.friction),
        (
            "Jᵀ F",
            &eq.kinematics.torques_for_base_wrench,
            &full.kinematics.torques_for_base_wrench,
        ),
    ]
}

type Matrices<'a> = [(
    &'a str,
    &'a [Vec<dynamics_codegen::symbolic::NodeId>],
    &'a [Vec<dynamics_codegen::symbolic::NodeId>],
); 2];

fn matrices<'a>(eq: &'a Equations, full: &'a Equations) -> Matrices<'a> {
    [
        ("M", &eq.mass, &full.mass),
        ("C", &eq.coriolis, &full.coriolis),
    ]
}

/// `M q̈ = τ − h − f` at the forward dynamics' q̈, and `M⁻¹ M = 1`.
fn forward(eq: &Equations, at: &Values, tau: &[f64]) {
    let m = at.matrix(&eq.mass);
    let qdd = at.vector(&eq.forward.qdd);
    let (h, f) = (at.vector(&eq.bias), at.vector(&eq.friction));
    let m_qdd = times(&m, &column(&qdd)).concat();
    let rhs: Vec<f64> = (0..tau.len()).map(|i| tau[i] - h[i] - f[i]).collect();
    close(&m_qdd, &rhs, 1e-10, "forward dynamics");
    let product = times(&at.matrix(&eq.forward.mass_inverse), &m);
    let n = tau.len();
    let identity: Vec<f64> = (0..n * n)
        .map(|k| f64::from(u8::from(k % (n + 1) == 0)))
        .collect();
    close(&product.concat(), &identity, 1e-10, "M⁻¹ M");
}

/// `∂τ/∂q` and `∂τ/∂q̇` are `Sᵀ · S` of the free robot's; `∂q̈/∂τ = M⁻¹`.
fn derivatives(eq: &Equations, full: &Equations, at: &Values, at_full: &Values, s: &[Vec<f64>]) {
    let (d, d_full) = (
        eq.derivatives.as_ref().expect("traced"),
        full.derivatives.as_ref().expect("traced"),
    );
    for which in 0..2 {
        let want = sandwiched(s, &at_full.matrix(&d_full.inverse[which]));
        close(&at.matrix(&d.inverse[which]).concat(), &want, 1e-12, "∂τ");
    }
    let inverse = at.matrix(&eq.forward.mass_inverse).concat();
    close(&at.matrix(&d.forward[2]).concat(), &inverse, 1e-12, "∂q̈/∂τ");
}

/// A tree: a revolute joint following its sibling with k = −0.7, o = 0.3 (and both with θ
/// offsets, so its sine and cosine are of `k q + o + θ`), a prismatic one following its cousin
/// with k = 1, o = 0.
pub(super) fn tree() -> Robot {
    let specs = [
        at(None, R, 0.0, 0.0, 0.0),
        at(Some(0), R, 0.3, 0.1, 1.0),
        at(Some(0), R, -0.2, 0.05, 2.0),
        at(Some(1), P, 0.0, 0.0, 3.0),
        at(Some(2), R, 0.1, 0.0, 4.0),
        at(Some(2), P, 0.0, 0.2, 5.0),
    ];
    let mut tree = robot(&specs, true);
    follow(&mut tree, 2, 1, -0.7, 0.3);
    follow(&mut tree, 5, 3, 1.0, 0.0);
    tree
}

#[test]
fn a_tree_with_mimic_joints_is_its_free_robot_projected() {
    check(&with_drives(tree()));
}

/// A serial chain whose last joint follows the first with k = −1, o = 0 and no θ offsets:
/// its sine and cosine are the first joint's (−sin q₁, cos q₁), no new sine computed.
#[test]
fn a_chain_whose_last_joint_mirrors_the_first() {
    let specs = [
        at(None, R, 0.0, 0.0, 0.0),
        at(None, R, 0.0, 0.0, 1.0),
        at(None, R, 0.0, 0.0, 2.0),
    ];
    let mut chain = robot(&specs, false);
    chain
        .joints
        .iter_mut()
        .for_each(|j| j.theta = Value::zero());
    follow(&mut chain, 2, 0, -1.0, 0.0);
    let chain = with_drives(chain);
    check(&chain);
    let (eq, _) = equations(&chain, FamilySet::default(), None);
    let of_q = |a: dynamics_codegen::symbolic::NodeId| eq.graph.constant(a).is_none();
    let sines = eq.graph.nodes().filter(|(_, node)| {
        matches!(node, dynamics_codegen::symbolic::Node::Sin(a) | dynamics_codegen::symbolic::Node::Cos(a) if of_q(*a))
    });
    assert_eq!(sines.count(), 0, "a sine of a joint angle traced as a node");
}

/// The Panda of its URDF, whose second finger follows the first (`k = 1`, `o = 0`): 9 joints,
/// 8 coordinates.
pub(super) fn panda() -> dynamics_codegen::pipeline::Loaded {
    use dynamics_codegen::pipeline::{load, Source};
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf/panda.urdf");
    let text = std::fs::read_to_string(path).expect("readable");
    let source = Source {
        path: "panda.urdf",
        text: Some(&text),
        chain: dynamics_codegen::front::Chain {
            base: Some("panda_link0"),
            ..Default::default()
        },
        ..Source::default()
    };
    let panda = load(&source).expect("loads");
    assert_eq!((panda.robot.dof(), panda.robot.coordinates().len()), (9, 8));
    panda
}

/// The Panda with its URDF's mimic finger through every other route out of the door: the C
/// header, the Rust module and the readable equations have 8 coordinates and no panic; the
/// regressor and the base parameters have 8 rows and 9 links, in the module's trait too.
#[test]
fn the_panda_with_a_mimic_finger_out_of_the_door() {
    use dynamics_codegen::inspect::Format;
    use dynamics_codegen::pipeline::Readable;
    let panda = panda();
    let families = FamilySet::default().with(Family::Derivatives);
    let header = panda.c_header(families, None, None).expect("a header");
    assert_eq!(header.dof, 8);
    let text = &header.text;
    assert!(text.contains("const double q[8]") && !text.contains("q[9]"));
    let module = panda.rust_module(families, None).expect("a module");
    let items = module.items.to_string();
    let dimensions = items.contains("Dynamics < 8usize >") && !items.contains("9usize");
    assert!(
        dimensions,
        "the module's dimensions are not the 8 coordinates"
    );
    for what in [Readable::Motion, Readable::Kinematics] {
        panda.readable(what, Format::Text).expect("readable");
    }
    let families = FamilySet::default()
        .with(Family::Regressor)
        .with(Family::BaseParameters);
    let eq = panda.equations(families, None).expect("traced");
    let regressor = eq.regressor.as_ref().expect("a regressor");
    assert_eq!(
        (regressor.columns.len(), regressor.columns[0].len()),
        (8, 9)
    );
    assert!(eq.base_parameters.is_some());
    let items = panda.rust_module(families, None).expect("a module").items;
    let items = items.to_string();
    assert!(
        items.contains("DynamicsRegressor < 8usize , 9usize >"),
        "{items:.300}"
    );
}
