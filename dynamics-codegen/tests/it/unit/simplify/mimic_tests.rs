//! The simplified models of robots with mimic joints, through the front door: a mimic joint's
//! `sin(k q_j + c)` and `cos(k q_j + c)` are symbols of their own, bounded over q_j's range
//! through k and c; the pruned outputs stay within their bounds at random states of the
//! envelope, on the small mimic arm (a revolute joint following another with k = −0.7) and the
//! Panda's URDF (its second finger following the first), over the URDF's own limits.

use crate::unit::simplify::tests::{sample, within_bounds};
use dynamics_codegen::method::{FamilySet, Method};
use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
use dynamics_codegen::pipeline::{load, Loaded, Source};
use dynamics_codegen::poly::{MimicAngle, Sym};
use dynamics_codegen::simplify::bound::symbol_bound;
use dynamics_codegen::simplify::{prune_outputs, Caps};
use dynamics_codegen::symbolic::Number;
use dynamics_test_support::Rng;

fn loaded(file: &str) -> Loaded {
    let path = format!("{}/../{file}", env!("CARGO_MANIFEST_DIR"));
    load(&Source::file(&path)).expect("loads")
}

/// `sin(−0.7 q + 0.3)` over q ∈ [0.5, 1.5] is the sine over [−0.75, −0.05] (k < 0 turns the
/// range over): at most sin 0.75; its cosine at most cos 0.05, at the end nearest 0.
#[test]
fn a_mimic_angle_is_bounded_through_its_rule() {
    let envelope = Envelope {
        joints: vec![JointEnvelope {
            lower: 0.5,
            upper: 1.5,
            speed: 1.0,
            acceleration: 1.0,
        }],
    };
    let angle = MimicAngle {
        joint: 0,
        multiplier: Number::ratio(-7, 10).expect("a ratio"),
        offset: Number::ratio(3, 10).expect("a ratio"),
    };
    let sin = symbol_bound(&Sym::MimicSin(angle), &envelope, &[]).expect("bounded");
    let cos = symbol_bound(&Sym::MimicCos(angle), &envelope, &[]).expect("bounded");
    assert!(sin >= 0.75f64.sin() && sin - 0.75f64.sin() < 1e-9, "{sin}");
    assert!(cos >= 0.05f64.cos() && cos - 0.05f64.cos() < 1e-9, "{cos}");
    // A coordinate past the envelope is refused, named.
    let past = MimicAngle { joint: 3, ..angle };
    let error = symbol_bound(&Sym::MimicSin(past), &envelope, &[]).expect_err("refused");
    assert!(error.contains("joint 4"), "{error}");
}

/// The small mimic arm over q ∈ [−1, 1.5] (its mimic angle then spans 1.75 rad, not a whole
/// turn), at 2 % of each coordinate's sampled peak torque: every output pruned within its
/// bound, the mimic angle's sine or cosine among the terms, and with a zero tolerance the
/// pruned outputs are the exact ones (the mimic leaves built back as they were traced).
#[test]
fn a_mimic_arm_is_pruned_within_its_bounds() {
    let arm = loaded("tests/data/trees/mimic_arm.toml");
    let eq = arm.equations(FamilySet::default(), None).expect("traces");
    assert_eq!(eq.dof, 3);
    let joint = JointEnvelope {
        lower: -1.0,
        upper: 1.5,
        speed: 2.0,
        acceleration: 5.0,
    };
    let envelope = Envelope {
        joints: vec![joint; 3],
    };
    let mut rng = Rng::new(41);
    let mut peak = [0.0f64; 3];
    for _ in 0..300 {
        let values = sample(&eq, &envelope, &mut rng);
        for (p, id) in peak.iter_mut().zip(&eq.tau) {
            *p = p.max(values[id.index()].abs());
        }
    }
    let request = Simplification {
        tolerance: peak.iter().map(|p| p * 0.02).collect(),
        envelope: envelope.clone(),
    };
    let pruned = prune_outputs(&eq, &request, Caps::NONE).expect("prunes");
    let mimic = |s: &Sym| matches!(s, Sym::MimicSin(_) | Sym::MimicCos(_));
    let reads_mimic = pruned
        .iter()
        .flat_map(|o| o.elements.as_ref().ok())
        .any(|e| {
            e.iter().any(|p| {
                p.pruning
                    .full
                    .keys()
                    .any(|m| m.factors().iter().any(|(s, _)| mimic(s)))
            })
        });
    assert!(reads_mimic, "no term holds the mimic angle");
    let eq = arm
        .equations(FamilySet::default(), Some(&request))
        .expect("simplifies");
    let ratios = within_bounds(&eq, &envelope, &mut rng, 2000, "mimic_arm");
    assert!(ratios.iter().any(|r| *r > 0.1), "{ratios:?}");
    let exact = Simplification {
        tolerance: vec![0.0; 3],
        envelope: envelope.clone(),
    };
    let eq = arm
        .equations(FamilySet::default(), Some(&exact))
        .expect("simplifies");
    let s = eq.simplified.as_ref().expect("simplified");
    let values = sample(&eq, &envelope, &mut rng);
    for o in &s.outputs {
        let exact = dynamics_codegen::simplify::elements(o.exact.shape(&eq));
        for ((_, _, e), (_, _, p)) in exact.upper().zip(o.elements.upper()) {
            let (x, y) = (values[e.index()], values[p.index()]);
            assert!(
                (x - y).abs() <= 1e-9 * (1.0 + x.abs()),
                "{:?}: {x} vs {y}",
                o.method
            );
        }
    }
}

/// The Panda's URDF with its mimic finger, its envelope and rated torques from its `<limit>`s
/// (per coordinate: 8, the finger's [0, 0.04] m at 0.2 m/s) at 1 %: g is pruned, every output
/// within its bound at random states of the URDF's ranges.
#[test]
fn the_mimic_panda_is_pruned_within_its_bounds() {
    let panda = loaded("robots/urdf/panda.urdf");
    assert!(panda.robot.has_mimics());
    let request = panda
        .simplification(&[("tolerance_percent", vec![1.0])])
        .expect("resolves")
        .expect("asked");
    let joints = &request.envelope.joints;
    assert_eq!((joints.len(), request.tolerance.len()), (8, 8));
    assert_eq!(
        (joints[7].lower, joints[7].upper, joints[7].speed),
        (0.0, 0.04, 0.2)
    );
    assert_eq!((joints[3].lower, joints[3].upper), (-3.0718, -0.0698));
    assert!(
        (request.tolerance[0] - 0.87).abs() < 1e-12 && (request.tolerance[7] - 1.0).abs() < 1e-12
    );
    let eq = panda
        .equations(FamilySet::default(), Some(&request))
        .expect("simplifies");
    let s = eq.simplified.as_ref().expect("simplified");
    let gravity = s.output(Method::GravityTorquesSimplified).expect("g");
    assert_eq!(gravity.fallback, None);
    assert!(gravity.bounds.all().any(|b| b.kept < b.terms));
    within_bounds(&eq, &request.envelope, &mut Rng::new(7), 1000, "panda.urdf");
}
