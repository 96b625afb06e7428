//! The proven bound against sampling: the full polynomial is τ (the graph's), and the pruned
//! one never strays from it by more than the bound at random states of the envelope.

use dynamics_codegen::model::{Envelope, JointEnvelope, Robot, Simplification};
use dynamics_codegen::simplify::eval::{Constants, State, Terms};
use dynamics_codegen::simplify::{prune_outputs, Caps, Pruning};
use dynamics_codegen::symbolic::Var;
use dynamics_codegen::trace::{derive, Equations};
use dynamics_test_support::Rng;
use std::f64::consts::PI;

fn load(file: &str) -> (Robot, Equations) {
    let path = format!("{}/../{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the robot file");
    let robot = dynamics_codegen::front::load(&path, &text)
        .expect("a robot")
        .robot;
    let eq = derive(&robot);
    (robot, eq)
}

fn envelope(n: usize) -> Envelope {
    let joint = JointEnvelope {
        lower: -PI,
        upper: PI,
        speed: 2.0,
        acceleration: 5.0,
    };
    Envelope {
        joints: vec![joint; n],
    }
}

/// A random state inside `e`: positions, velocities, accelerations.
fn state(rng: &mut Rng, e: &Envelope) -> [Vec<f64>; 3] {
    let mut q = Vec::new();
    let mut qd = Vec::new();
    let mut qdd = Vec::new();
    for j in &e.joints {
        q.push(rng.range(j.lower, j.upper));
        qd.push(rng.range(-j.speed, j.speed));
        qdd.push(rng.range(-j.acceleration, j.acceleration));
    }
    [q, qd, qdd]
}

/// τ from the graph, as `dynamics eval` evaluates it.
fn graph_tau(eq: &Equations, offsets: &[f64], [q, qd, qdd]: &[Vec<f64>; 3]) -> Vec<f64> {
    let values = eq.graph.eval(|v| match v {
        Var::Q(i) => q[usize::from(i)],
        Var::SinQ(i) => (q[usize::from(i)] + offsets[usize::from(i)]).sin(),
        Var::CosQ(i) => (q[usize::from(i)] + offsets[usize::from(i)]).cos(),
        Var::Qd(i) => qd[usize::from(i)],
        Var::Qdd(i) => qdd[usize::from(i)],
        _ => f64::NAN,
    });
    eq.tau.iter().map(|id| values[id.index()]).collect()
}

/// Each joint's tolerance: `fraction` of its peak |τ| over `samples` random states.
fn tolerances(eq: &Equations, offsets: &[f64], e: &Envelope, fraction: f64) -> Vec<f64> {
    let mut rng = Rng::new(7);
    let mut peak = vec![0.0f64; eq.dof];
    for _ in 0..500 {
        let s = state(&mut rng, e);
        for (p, t) in peak.iter_mut().zip(graph_tau(eq, offsets, &s)) {
            *p = p.max(t.abs());
        }
    }
    peak.iter().map(|p| fraction * p).collect()
}

/// τ's elements pruned over `e` within `tolerance`, with no cap, as `dynamics inspect
/// --simplified` prunes them.
fn tau_prunings(eq: &Equations, e: &Envelope, tolerance: &[f64]) -> Result<Vec<Pruning>, String> {
    let request = Simplification {
        tolerance: tolerance.to_vec(),
        envelope: e.clone(),
    };
    let outputs = prune_outputs(eq, &request, Caps::NONE)?;
    let tau = outputs.into_iter().next().expect("τ first").elements;
    Ok(tau
        .expect("no cap")
        .into_iter()
        .map(|p| p.pruning)
        .collect())
}

/// The worst `|full − kept|` per joint over `samples` random states; checks on the way that
/// the full polynomial is the graph's τ to 1e-9 of its size.
fn worst_errors(prunings: &[Pruning], eq: &Equations, e: &Envelope, samples: usize) -> Vec<f64> {
    let constants = dynamics_codegen::simplify::eval::constants(eq).expect("constants");
    let k: &Constants = &constants;
    let mut rng = Rng::new(11);
    let mut worst = vec![0.0f64; eq.dof];
    let ready = |t| Terms::new(t).expect("exponents fit");
    let polynomials: Vec<_> = prunings
        .iter()
        .map(|p| (ready(&p.full), ready(&p.kept)))
        .collect();
    for _ in 0..samples {
        let x = state(&mut rng, e);
        let at = State {
            q: &x[0],
            qd: &x[1],
            qdd: &x[2],
        };
        let tau = graph_tau(eq, &k.offsets, &x);
        for (i, (full, kept)) in polynomials.iter().enumerate() {
            let full = full.eval(at, k).expect("numeric");
            let kept = kept.eval(at, k).expect("numeric");
            let scale = 1.0 + tau[i].abs();
            assert!(
                (full - tau[i]).abs() <= 1e-9 * scale,
                "T{}: polynomial {full} vs graph {}",
                i + 1,
                tau[i]
            );
            worst[i] = worst[i].max((full - kept).abs());
        }
    }
    worst
}

/// Prunes `file`'s τ at `fraction` of each joint's sampled peak and samples the error.
fn check_sound(file: &str, fraction: f64, samples: usize) {
    let (_, eq) = load(file);
    let e = envelope(eq.dof);
    let offsets = dynamics_codegen::simplify::eval::constants(&eq)
        .expect("constants")
        .offsets;
    let tol = tolerances(&eq, &offsets, &e, fraction);
    let prunings = tau_prunings(&eq, &e, &tol).expect("prunes");
    let worst = worst_errors(&prunings, &eq, &e, samples);
    let mut dropped = 0;
    for (i, p) in prunings.iter().enumerate() {
        assert!(
            p.bound <= p.tolerance,
            "T{}: bound over the tolerance",
            i + 1
        );
        assert!(
            worst[i] <= p.bound,
            "T{}: sampled error {} over the proven bound {}",
            i + 1,
            worst[i],
            p.bound
        );
        dropped += p.dropped.len();
        eprintln!(
            "{file} T{}: {} of {} kept, tolerance {:.4}, bound {:.4}, worst sampled {:.4}, ratio {:.3}",
            i + 1,
            p.kept.len(),
            p.full.len(),
            p.tolerance,
            p.bound,
            worst[i],
            worst[i] / p.bound.max(f64::MIN_POSITIVE)
        );
    }
    assert!(dropped > 0, "{file}: nothing dropped, nothing tested");
}

#[test]
fn puma_560_within_its_bound() {
    check_sound("robots/puma560.toml", 0.01, 3000);
}

#[test]
fn a_random_robot_within_its_bound() {
    check_sound("tests/data/reference/robots/random5.json", 0.01, 2000);
}

/// Coulomb friction's `sgn θ'` is bounded by 1 and a geared rotor's inertia is in M.
#[test]
fn friction_and_rotors_within_their_bound() {
    check_sound("robots/two_link_friction.toml", 0.05, 3000);
}

#[test]
fn a_zero_tolerance_keeps_everything_and_a_huge_one_nothing() {
    let (_, eq) = load("robots/puma560.toml");
    let e = envelope(eq.dof);
    let all = tau_prunings(&eq, &e, &[0.0; 6]).expect("prunes");
    for p in &all {
        assert_eq!((p.kept.len(), p.bound), (p.full.len(), 0.0));
    }
    let none = tau_prunings(&eq, &e, &[1e9; 6]).expect("prunes");
    for p in &none {
        assert!(p.kept.is_empty() && p.bound <= p.magnitude * (1.0 + 1e-9));
        assert!(p.bound > 0.0);
    }
}

#[test]
fn a_parameter_cannot_be_bounded() {
    let (_, eq) = load("robots/niku_example_6_1.toml");
    let error = tau_prunings(&eq, &envelope(1), &[0.1]).expect_err("refused");
    assert!(error.contains("the parameter `"), "{error}");
    assert!(error.starts_with("T1: "), "{error}");
}
