//! `simplify(...)` through the derive on robots with mimic joints: the small mimic arm's
//! description file (its third joint follows the second, `q₃ = −0.7 q₂ + 0.3`, so its sine is
//! of `−0.7 q₂ + 0.3 + θ₃`) and the Panda's URDF with both fingers (the second following the
//! first), the envelope and tolerances one per coordinate. The pruned outputs against the exact
//! methods at random states of the envelope, within the bounds the generator proves for the
//! same request through the front door (`simplified::check_within`).

use crate::simplified::check_within;
use dynamics_codegen::method::FamilySet;
use dynamics_codegen::model::Simplification;
use dynamics_codegen::pipeline::{load, Loaded, Source};
use dynamics_codegen::trace::PrunedElement;
use dynamics_codegen::Method;
use dynamics_runtime::Dynamics;

/// The small mimic arm as its file's `[simplify]` asks: q ∈ [−1, 1.5] (its mimic angle spans
/// 1.75 rad), about 2 % of its peak torques there.
#[derive(Dynamics)]
#[dynamics(file = "data/trees/mimic_arm.toml")]
struct MimicArm;

/// The Panda with its hand and fingers (every branch), at 1 % of its URDF's efforts over its
/// `<limit>`s, per coordinate: 8, the finger's [0, 0.04] m.
#[derive(Dynamics)]
#[dynamics(urdf = "../robots/urdf/panda.urdf", simplify(tolerance_percent = 1))]
struct MimicPanda;

fn loaded(file: &str) -> Loaded {
    let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
    load(&Source::file(&path)).expect("loads")
}

/// The request `overrides` make of `file`'s, its proven bounds, and which outputs are exact.
fn request(
    file: &str,
    overrides: &[(&'static str, Vec<f64>)],
) -> (Simplification, ([Vec<PrunedElement>; 4], [bool; 4])) {
    let robot = loaded(file);
    let request = robot
        .simplification(overrides)
        .expect("resolves")
        .expect("asked");
    let eq = robot
        .equations(FamilySet::default(), Some(&request))
        .expect("simplifies");
    let s = eq.simplified.expect("simplified");
    let outputs = [
        Method::InverseDynamicsSimplified,
        Method::GravityTorquesSimplified,
        Method::CoriolisTorquesSimplified,
        Method::MassMatrixSimplified,
    ]
    .map(|m| s.output(m).expect("an output of the family"));
    let bounds = outputs.map(|o| o.bounds.all().copied().collect());
    (request, (bounds, outputs.map(|o| o.fallback.is_some())))
}

#[test]
fn a_mimic_arm_simplified_within_its_proven_bounds() {
    let file = "data/trees/mimic_arm.toml";
    let (request, bounds) = request(file, &[]);
    assert_eq!(request.tolerance, [0.1, 0.25, 0.003]);
    assert_eq!(bounds.1, [false; 4], "every output pruned");
    let ratio = check_within(&MimicArm, file, &request, bounds);
    assert!(ratio > 0.1, "the bound is vacuous: best ratio {ratio}");
}

/// g pruned within its bounds (the fingers' rows too), τ, C q̇ and M left exact as the serial
/// Panda's are.
#[test]
fn the_mimic_panda_simplified_within_its_proven_bounds() {
    let file = "../robots/urdf/panda.urdf";
    let (request, bounds) = request(file, &[("tolerance_percent", vec![1.0])]);
    assert_eq!(request.envelope.joints.len(), 8);
    assert_eq!(
        bounds.1,
        [true, false, true, true],
        "τ, g, C q̇, M left exact"
    );
    let ratio = check_within(&MimicPanda, file, &request, bounds);
    assert!(ratio > 0.1, "the bound is vacuous: best ratio {ratio}");
}
