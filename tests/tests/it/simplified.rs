//! `simplify(...)` through the derive: the pruned τ, M, C q̇ and g against the exact methods of the
//! same robot (the oracle) at random states of the envelope, never further apart than the
//! proven bound, which the generator gives for the same request; and the ratio of the worst
//! sampled error to that bound, printed (`--nocapture`) to show that it is not vacuous.

use dynamics_codegen::front::{joint_limits, load_urdf, Chain};
use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
use dynamics_codegen::trace::PrunedElement;
use dynamics_codegen::Method;
use dynamics_runtime::{Dynamics, DynamicsSimplified};
use dynamics_test_support::Rng;

/// PUMA 560 at about 1 % of its peak torques over the envelope below (sampled: 22, 60, 13,
/// 0.04, 0.05 and 0.001 N·m).
#[derive(Dynamics)]
#[dynamics(
    file = "../robots/puma560.toml",
    simplify(
        tolerance = [0.22, 0.6, 0.13, 0.0004, 0.0005, 0.00001],
        q_min = -2.5,
        q_max = 2.0,
        qd_max = 2,
        qdd_max = 5,
    )
)]
struct Puma;

/// A random 3-joint robot of the reference data, its tolerance relative to a stated torque.
/// (A 6-joint random arm keeps too many terms to be worth it: `simplify/tests.rs`.)
#[derive(Dynamics)]
#[dynamics(
    file = "data/reference/robots/random2.json",
    simplify(rated = [20, 10, 5], tolerance_percent = 1, qd_max = [1, 2, 3])
)]
struct Random;

/// The UR5 of its URDF: the range and speed of the envelope are its `<limit>`s, and the
/// rated torques of `tolerance_percent` its `effort`s.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/ur5.urdf",
    simplify(tolerance_percent = 1, qdd_max = 4)
)]
struct Ur5;

/// The Panda of its URDF (to panda_link8, the hand fixed to it) at 1 % of its rated torques
/// (the URDF's `effort`, Franka's datasheet: 87 N·m joints 1-4, 12 N·m joints 5-7) over its
/// `<limit>`s' ranges and speeds, |q̈| ≤ 5 (the default: the URDF gives no acceleration). Its τ
/// and M are too large to prune and stay exact; its g is pruned.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/panda.urdf",
    tip = "panda_link8",
    simplify(rated = [87, 87, 87, 87, 12, 12, 12], tolerance_percent = 1)
)]
struct Panda;

/// A two-link arm whose description file asks for its simplified models (`[simplify]`).
#[derive(Dynamics)]
#[dynamics(file = "data/simplify/two_link.toml")]
struct TwoLink;

/// The same requests, for the generator's bounds.
fn puma_request() -> Simplification {
    let joint = JointEnvelope {
        lower: -2.5,
        upper: 2.0,
        speed: 2.0,
        acceleration: 5.0,
    };
    Simplification {
        tolerance: vec![0.22, 0.6, 0.13, 0.0004, 0.0005, 0.00001],
        envelope: Envelope {
            joints: vec![joint; 6],
        },
    }
}

/// The random robot's request: the default ranges (±π rad for its revolute joints 1 and 3,
/// ±1 m for its prismatic joint 2), its speeds, the default acceleration.
fn random_request() -> Simplification {
    let pi = std::f64::consts::PI;
    let joints = [(pi, 1.0), (1.0, 2.0), (pi, 3.0)].map(|(range, speed)| JointEnvelope {
        lower: -range,
        upper: range,
        speed,
        acceleration: 5.0,
    });
    Simplification {
        tolerance: vec![0.2, 0.1, 0.05],
        envelope: Envelope {
            joints: joints.to_vec(),
        },
    }
}

/// The request of `data/simplify/two_link.toml`.
fn two_link_request() -> Simplification {
    let joints = [(-1.0, 1.0), (-2.0, 2.0)].map(|(lower, upper)| JointEnvelope {
        lower,
        upper,
        speed: 3.0,
        acceleration: 5.0,
    });
    Simplification {
        tolerance: vec![0.5, 0.3],
        envelope: Envelope {
            joints: joints.to_vec(),
        },
    }
}

/// The envelope of a URDF's `<limit>`s, read here by the front end's reader of them, with
/// `acceleration` for every joint.
fn urdf_envelope(file: &str, chain: Chain, acceleration: f64) -> Envelope {
    let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("the URDF");
    let limits = joint_limits(&text, chain).expect("limits");
    let joints = limits.iter().map(|l| JointEnvelope {
        lower: l.lower.expect("a range"),
        upper: l.upper.expect("a range"),
        speed: l.velocity.expect("a speed"),
        acceleration,
    });
    Envelope {
        joints: joints.collect(),
    }
}

/// The UR5's request: its URDF's limits, and 1 % of the efforts the file writes (150 N·m for
/// the shoulder and elbow, 28 N·m for the wrist).
fn ur5_request() -> Simplification {
    Simplification {
        tolerance: vec![1.5, 1.5, 1.5, 0.28, 0.28, 0.28],
        envelope: urdf_envelope("../robots/urdf/ur5.urdf", Chain::default(), 4.0),
    }
}

/// The Panda's request: 1 % of 87 and 12 N·m, its URDF's limits.
fn panda_request() -> Simplification {
    let chain = Chain {
        base: None,
        tip: Some("panda_link8"),
        tips: &[],
    };
    Simplification {
        tolerance: vec![0.87, 0.87, 0.87, 0.87, 0.12, 0.12, 0.12],
        envelope: urdf_envelope("../robots/urdf/panda.urdf", chain, 5.0),
    }
}

/// The proven bounds of τ, g, C q̇ and M (rows) of the robot in `file` for `request`, and
/// whether each of the four is left exact.
fn bounds(file: &str, request: &Simplification) -> ([Vec<PrunedElement>; 4], [bool; 4]) {
    let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the robot file");
    let robot = if file.ends_with(".urdf") {
        // The Panda's fingers branch below its hand: its chain ends at panda_link8.
        let tip = file.contains("panda").then_some("panda_link8");
        load_urdf(
            &path,
            &text,
            Chain {
                base: None,
                tip,
                tips: &[],
            },
            true,
        )
        .expect("a robot")
    } else {
        dynamics_codegen::front::load(&path, &text).expect("a robot")
    }
    .robot;
    let mut eq = dynamics_codegen::derive(&robot);
    dynamics_codegen::simplify::add(&mut eq, request).expect("simplifies");
    let s = eq.simplified.expect("simplified");
    let outputs = [
        Method::InverseDynamicsSimplified,
        Method::GravityTorquesSimplified,
        Method::CoriolisTorquesSimplified,
        Method::MassMatrixSimplified,
    ]
    .map(|m| s.output(m).expect("an output of the family"));
    // M row by row, n × n.
    let bounds = outputs.map(|o| o.bounds.all().copied().collect());
    (bounds, outputs.map(|o| o.fallback.is_some()))
}

/// Samples `robot` in the envelope; asserts every pruned output within its bound, and every
/// output left exact equal to the exact method to rounding; returns the largest ratio of the
/// worst sampled error to the bound among the elements where something was dropped.
fn check<const N: usize, R: DynamicsSimplified<N>>(
    robot: &R,
    file: &str,
    request: &Simplification,
) -> f64 {
    check_within(robot, file, request, bounds(file, request))
}

/// [`check`] with the generator's bounds and outputs left exact given.
pub(crate) fn check_within<const N: usize, R: DynamicsSimplified<N>>(
    robot: &R,
    file: &str,
    request: &Simplification,
    ([tau_b, g_b, c_b, m_b], exact): ([Vec<PrunedElement>; 4], [bool; 4]),
) -> f64 {
    let mut rng = Rng::new(17);
    let mut worst = [
        vec![0.0f64; N],
        vec![0.0; N],
        vec![0.0; N],
        vec![0.0; N * N],
    ];
    for _ in 0..3000 {
        let e = &request.envelope.joints;
        let q: [f64; N] = std::array::from_fn(|i| rng.range(e[i].lower, e[i].upper));
        let qd: [f64; N] = std::array::from_fn(|i| rng.range(-e[i].speed, e[i].speed));
        let qdd = std::array::from_fn(|i| rng.range(-e[i].acceleration, e[i].acceleration));
        let tau = (
            robot.inverse_dynamics(&q, &qd, &qdd),
            robot.inverse_dynamics_simplified(&q, &qd, &qdd),
        );
        let g = (
            robot.gravity_torques(&q),
            robot.gravity_torques_simplified(&q),
        );
        let c = (
            robot.coriolis_torques(&q, &qd),
            robot.coriolis_torques_simplified(&q, &qd),
        );
        let m = (
            robot.mass_matrix(&q).concat(),
            robot.mass_matrix_simplified(&q).concat(),
        );
        let pairs = [
            (&tau.0[..], &tau.1[..]),
            (&g.0[..], &g.1[..]),
            (&c.0[..], &c.1[..]),
            (&m.0[..], &m.1[..]),
        ];
        for ((w, (x, y)), exact) in worst.iter_mut().zip(pairs).zip(exact) {
            // The same closed form, its sums possibly added in another order (the emission
            // orders them by when their terms are ready, which the family's shared code moves).
            let same = |(x, y): (&f64, &f64)| (x - y).abs() <= 1e-12 * x.abs().max(1.0);
            assert!(!exact || x.iter().zip(y).all(same), "{file}: {x:?} {y:?}");
            for (w, (x, y)) in w.iter_mut().zip(x.iter().zip(y)) {
                *w = w.max((x - y).abs());
            }
        }
    }
    let mut best_ratio = 0.0f64;
    for ((name, w), b) in ["tau", "g", "C qd", "M"]
        .iter()
        .zip(&worst)
        .zip([&tau_b, &g_b, &c_b, &m_b])
    {
        for (k, (w, b)) in w.iter().zip(b).enumerate() {
            assert!(
                *w <= b.bound + 1e-9,
                "{file} {name}[{k}]: sampled {w} over the proven bound {}",
                b.bound
            );
            if b.kept < b.terms {
                best_ratio = best_ratio.max(w / b.bound);
                eprintln!("{file} {name}[{k}]: {} of {} terms kept, bound {:.3e}, worst sampled {w:.3e}, ratio {:.3}", b.kept, b.terms, b.bound, w / b.bound);
            }
        }
    }
    best_ratio
}

#[test]
fn puma_560_simplified_within_its_proven_bounds() {
    let ratio = check(&Puma, "../robots/puma560.toml", &puma_request());
    assert!(ratio > 0.1, "the bound is vacuous: best ratio {ratio}");
}

#[test]
fn a_random_robot_simplified_within_its_proven_bounds() {
    let ratio = check(
        &Random,
        "data/reference/robots/random2.json",
        &random_request(),
    );
    assert!(ratio > 0.0, "nothing dropped");
}

#[test]
fn a_urdf_robot_simplified_within_its_limits() {
    let ratio = check(&Ur5, "../robots/urdf/ur5.urdf", &ur5_request());
    assert!(ratio > 0.0, "nothing dropped");
}

#[test]
fn simplified_as_the_description_file_asks() {
    let ratio = check(&TwoLink, "data/simplify/two_link.toml", &two_link_request());
    assert!(ratio > 0.0, "nothing dropped");
}

/// The Panda at 1 % of its rated torques: g pruned within its bounds; τ, C q̇ and M, whose
/// expanded forms are far larger than the exact ones, left exact (bound 0) and equal to the exact
/// methods to rounding.
#[test]
fn the_panda_simplified_within_its_proven_bounds() {
    let request = panda_request();
    let ([_, g, _, _], exact) = bounds("../robots/urdf/panda.urdf", &request);
    assert_eq!(exact, [true, false, true, true], "τ, g, C q̇, M left exact");
    assert!(g.iter().filter(|b| b.kept < b.terms).count() >= 5, "{g:?}");
    let ratio = check(&Panda, "../robots/urdf/panda.urdf", &request);
    assert!(ratio > 0.1, "the bound is vacuous: best ratio {ratio}");
}
