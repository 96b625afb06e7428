//! The generated pruned outputs against the exact ones, both evaluated from the graph at
//! random states of the envelope: never further apart than the proven bound, and not
//! vacuously (the worst sampled error is reported against the bound).

use dynamics_codegen::method::Method;
use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
use dynamics_codegen::simplify::{add, MAX_KEPT, MAX_WORK};
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::trace::{derive, Elements, Equations, Fallback, PrunedElement};
use dynamics_codegen::trace::{SimplifiedEquations, SimplifiedOutput};
use dynamics_test_support::Rng;

fn load(file: &str) -> Equations {
    let path = format!("{}/../{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the robot file");
    derive(
        &dynamics_codegen::front::load(&path, &text)
            .expect("a robot")
            .robot,
    )
}

fn envelope(n: usize) -> Envelope {
    let joint = JointEnvelope {
        lower: -2.5,
        upper: 2.0,
        speed: 2.0,
        acceleration: 5.0,
    };
    Envelope {
        joints: vec![joint; n],
    }
}

/// Every node's value at a random state of `e`.
pub(super) fn sample(eq: &Equations, e: &Envelope, rng: &mut Rng) -> Vec<f64> {
    let offsets = dynamics_codegen::simplify::eval::constants(eq)
        .expect("constants")
        .offsets;
    let pick = |rng: &mut Rng, f: fn(&JointEnvelope) -> (f64, f64)| -> Vec<f64> {
        e.joints
            .iter()
            .map(|j| {
                let (lo, hi) = f(j);
                rng.range(lo, hi)
            })
            .collect()
    };
    let q = pick(rng, |j| (j.lower, j.upper));
    let qd = pick(rng, |j| (-j.speed, j.speed));
    let qdd = pick(rng, |j| (-j.acceleration, j.acceleration));
    // NaN past the coordinates: a robot with mimic joints keeps its joints' own leaves in
    // the graph, read by no output.
    let at = |v: &[f64], i: u16| v.get(usize::from(i)).copied().unwrap_or(f64::NAN);
    eq.graph.eval(|v| match v {
        Var::Q(i) => at(&q, i),
        Var::SinQ(i) => (at(&q, i) + at(&offsets, i)).sin(),
        Var::CosQ(i) => (at(&q, i) + at(&offsets, i)).cos(),
        Var::Qd(i) => at(&qd, i),
        Var::Qdd(i) => at(&qdd, i),
        _ => f64::NAN,
    })
}

/// The exact and pruned nodes of τ, g, C q̇ and M's upper triangle, with their bounds and names.
fn pairs(eq: &Equations) -> Vec<(NodeId, NodeId, PrunedElement, String)> {
    let s = eq.simplified.as_ref().expect("simplified");
    let mut out = Vec::new();
    for o in &s.outputs {
        let exact = dynamics_codegen::simplify::elements(o.exact.shape(eq));
        let pruned = exact.upper().zip(o.elements.upper()).zip(o.named_bounds());
        for (((_, _, &e), (_, _, &p)), (name, _, &b)) in pruned {
            out.push((e, p, b, name));
        }
    }
    out
}

/// The output of `method` in `s`.
fn output(s: &SimplifiedEquations, method: Method) -> &SimplifiedOutput {
    s.output(method).expect("an output of the family")
}

/// The elements of a vector output.
fn vector<T>(e: &Elements<T>) -> &[T] {
    match e {
        Elements::Vector(v) => v,
        Elements::Matrix(_) => panic!("a matrix"),
    }
}

/// Prunes `file` at `fraction` of each joint's sampled peak torque; returns the worst
/// sampled error over the bound of every element that dropped something.
fn check_sound(file: &str, fraction: f64, samples: usize) -> Vec<f64> {
    let mut eq = load(file);
    let e = envelope(eq.dof);
    let mut rng = Rng::new(5);
    let mut peak = vec![0.0f64; eq.dof];
    for _ in 0..300 {
        let values = sample(&eq, &e, &mut rng);
        for (p, id) in peak.iter_mut().zip(&eq.tau) {
            *p = p.max(values[id.index()].abs());
        }
    }
    let tolerance = peak.iter().map(|p| p * fraction).collect();
    let request = Simplification {
        tolerance,
        envelope: e.clone(),
    };
    add(&mut eq, &request).expect("simplifies");
    within_bounds(&eq, &e, &mut rng, samples, file)
}

/// The worst error over `samples` random states of `e` of each element of the simplified
/// outputs of `eq` that dropped something, over its bound (asserted ≤ 1, and every bound within
/// its tolerance).
pub(super) fn within_bounds(
    eq: &Equations,
    e: &Envelope,
    rng: &mut Rng,
    samples: usize,
    file: &str,
) -> Vec<f64> {
    let pairs = pairs(eq);
    let mut worst = vec![0.0f64; pairs.len()];
    for _ in 0..samples {
        let values = sample(eq, e, rng);
        for (w, (exact, pruned, _, _)) in worst.iter_mut().zip(&pairs) {
            *w = w.max((values[exact.index()] - values[pruned.index()]).abs());
        }
    }
    let mut ratios = Vec::new();
    for (w, (_, _, b, name)) in worst.iter().zip(&pairs) {
        assert!(
            b.bound <= b.tolerance,
            "{file} {name}: bound over the tolerance"
        );
        // The evaluation's own rounding: far below any bound that matters.
        assert!(
            *w <= b.bound + 1e-9,
            "{file} {name}: sampled {w} over the proven bound {}",
            b.bound
        );
        if b.kept < b.terms {
            ratios.push(w / b.bound);
            eprintln!(
                "{file} {name}: {} of {} kept, bound {:.3e}, worst sampled {w:.3e}, ratio {:.3}",
                b.kept,
                b.terms,
                b.bound,
                w / b.bound
            );
        }
    }
    assert!(
        !ratios.is_empty(),
        "{file}: nothing dropped, nothing tested"
    );
    ratios
}

#[test]
fn puma_560_pruned_within_its_bounds() {
    let ratios = check_sound("robots/puma560.toml", 0.01, 2000);
    // Not vacuous: somewhere sampling comes within a factor of 10 of the bound.
    assert!(ratios.iter().any(|r| *r > 0.1), "{ratios:?}");
}

#[test]
fn a_random_robot_pruned_within_its_bounds() {
    check_sound("tests/data/reference/robots/random2.json", 0.01, 2000);
}

#[test]
fn friction_pruned_within_its_bounds() {
    check_sound("robots/two_link_friction.toml", 0.05, 2000);
}

/// A zero tolerance keeps every term: the pruned outputs are the exact ones, factored.
#[test]
fn a_zero_tolerance_keeps_the_exact_values() {
    let mut eq = load("robots/puma560.toml");
    let request = Simplification {
        tolerance: vec![0.0; 6],
        envelope: envelope(6),
    };
    add(&mut eq, &request).expect("simplifies");
    let values = sample(&eq, &envelope(6), &mut Rng::new(3));
    for (exact, pruned, b, name) in pairs(&eq) {
        assert_eq!((b.kept, b.bound), (b.terms, 0.0), "{name}");
        let (x, y) = (values[exact.index()], values[pruned.index()]);
        assert!(
            (x - y).abs() <= 1e-9 * (1.0 + x.abs()),
            "{name}: {x} vs {y}"
        );
    }
}

#[test]
fn a_parameter_is_refused() {
    let mut eq = load("robots/niku_example_6_1.toml");
    let request = Simplification {
        tolerance: vec![0.1],
        envelope: envelope(1),
    };
    let error = add(&mut eq, &request).expect_err("refused");
    assert!(error.contains("the parameter `"), "{error}");
    assert!(eq.simplified.is_none());
}

/// A pruned output that would keep too many terms is left exact, the others still pruned:
/// expanded, a general robot's torques grow large (random5 keeps 3867 terms of τ at these
/// tolerances).
#[test]
fn an_output_too_large_is_left_exact() {
    let mut eq = load("tests/data/reference/robots/random5.json");
    let tolerance = vec![0.4, 0.3, 0.2, 0.1, 0.05, 0.02];
    let request = Simplification {
        tolerance,
        envelope: envelope(6),
    };
    add(&mut eq, &request).expect("simplifies");
    let s = eq.simplified.as_ref().expect("simplified");
    let (tau, mass) = (
        output(s, Method::InverseDynamicsSimplified),
        output(s, Method::MassMatrixSimplified),
    );
    let gravity = output(s, Method::GravityTorquesSimplified);
    let Some(Fallback::TooManyTerms { kept, cap }) = tau.fallback else {
        panic!("τ pruned: {:?}", tau.fallback);
    };
    assert!(kept > cap, "{kept} of {cap}");
    assert_eq!(vector(&tau.elements), eq.tau);
    assert!(tau.bounds.all().all(|b| (b.bound, b.kept) == (0.0, 0)));
    assert_eq!((mass.fallback, gravity.fallback), (None, None));
    let kept: usize = mass.bounds.upper().map(|(_, _, b)| b.kept).sum();
    assert!(kept < MAX_KEPT, "M keeps {kept}");
    assert!(mass.bounds.all().any(|b| b.kept < b.terms));
}

/// The Panda over its URDF's ranges and speeds at 1 % of its rated torques: its τ passes the
/// budget of work long before it is expanded (τ1 alone takes 30 million term operations and
/// keeps 9848 terms), so τ is exact; its M keeps more than the cap, so M is exact; its g is
/// pruned. Within the bounds, as the other robots.
#[test]
fn the_panda_prunes_g_and_leaves_tau_and_m_exact() {
    let mut eq = load("robots/panda.toml");
    let limits = [
        (-2.8973, 2.8973, 2.175),
        (-1.7628, 1.7628, 2.175),
        (-2.8973, 2.8973, 2.175),
        (-3.0718, -0.0698, 2.175),
        (-2.8973, 2.8973, 2.61),
        (-0.0175, 3.7525, 2.61),
        (-2.8973, 2.8973, 2.61),
    ];
    let joints = limits.map(|(lower, upper, speed)| JointEnvelope {
        lower,
        upper,
        speed,
        acceleration: 5.0,
    });
    let request = Simplification {
        tolerance: vec![0.87, 0.87, 0.87, 0.87, 0.12, 0.12, 0.12],
        envelope: Envelope {
            joints: joints.to_vec(),
        },
    };
    add(&mut eq, &request).expect("simplifies");
    let s = eq.simplified.as_ref().expect("simplified");
    let (tau, mass) = (
        output(s, Method::InverseDynamicsSimplified),
        output(s, Method::MassMatrixSimplified),
    );
    let gravity = output(s, Method::GravityTorquesSimplified);
    assert_eq!(
        tau.fallback,
        Some(Fallback::TooMuchWork { budget: MAX_WORK })
    );
    assert!(
        matches!(mass.fallback, Some(Fallback::TooManyTerms { kept, .. }) if kept > MAX_KEPT),
        "{:?}",
        mass.fallback
    );
    assert_eq!(vector(&tau.elements), eq.tau);
    assert_eq!(mass.elements, Elements::Matrix(eq.mass.clone()));
    assert_eq!(gravity.fallback, None);
    let gravity_bounds = vector(&gravity.bounds);
    let dropped = gravity_bounds.iter().filter(|b| b.kept < b.terms);
    assert!(dropped.count() >= 5, "{gravity_bounds:?}");
    let mut worst = [0.0f64; 7];
    let mut rng = Rng::new(11);
    for _ in 0..2000 {
        let values = sample(&eq, &request.envelope, &mut rng);
        for (w, (exact, pruned)) in worst
            .iter_mut()
            .zip(eq.gravity.iter().zip(vector(&gravity.elements)))
        {
            *w = w.max((values[exact.index()] - values[pruned.index()]).abs());
        }
    }
    for (i, (w, b)) in worst.iter().zip(gravity_bounds).enumerate() {
        assert!(*w <= b.bound + 1e-9, "D{}: {w} over {}", i + 1, b.bound);
    }
}

/// The derive documents each simplified method with every output's bound and the envelope,
/// and a robot that does not ask gets none of it.
#[test]
fn the_rustdoc_states_the_bounds_and_the_envelope() {
    let arm = "gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0], [q, 0, 0.5, 0]], \
               link(mass = 2, com = [-0.5, 0, 0]), link(mass = 1, com = [-0.25, 0, 0])";
    let derive = |extra: &str| {
        let text = format!("#[dynamics({arm}{extra})] struct Arm;");
        dynamics_codegen::derive_dynamics(text.parse().expect("tokens")).to_string()
    };
    let code = derive(", simplify(tolerance = [0.5, 0.1], qd_max = 1.5, q_min = -1, q_max = 1)");
    for method in [
        "inverse_dynamics",
        "mass_matrix",
        "coriolis_torques",
        "gravity_torques",
    ] {
        assert!(
            code.contains(&format!("fn {method}_simplified")),
            "{method}"
        );
    }
    assert!(code.contains("|T1 − T1,simplified| ≤ "), "{code}");
    assert!(code.contains("|D12 − D12,simplified| ≤ "), "{code}");
    assert!(
        code.contains("q2 in [-1, 1], |qd2| <= 1.5, |qdd2| <= 5"),
        "{code}"
    );
    let plain = derive("");
    assert!(!plain.contains("simplified"), "{plain}");
}

/// An output left exact says so in its method's rustdoc, in place of bounds; the outputs
/// pruned beside it keep theirs.
#[test]
fn the_rustdoc_says_which_output_is_exact() {
    let text = "#[dynamics(file = \"../tests/data/reference/robots/random5.json\", \
                simplify(tolerance = [0.4, 0.3, 0.2, 0.1, 0.05, 0.02]))] struct Arm;";
    let code = dynamics_codegen::derive_dynamics(text.parse().expect("tokens")).to_string();
    assert!(
        code.contains("Left exact: the same values as `inverse_dynamics` (bound 0).")
            && code.contains("Not pruned: its pruned expansion keeps "),
        "{code}"
    );
    assert!(!code.contains("|T1 − T1,simplified|"), "{code}");
    assert!(code.contains("|D12 − D12,simplified| ≤ "), "{code}");
    assert!(code.contains("|D1 − D1,simplified| ≤ "), "{code}");
}
