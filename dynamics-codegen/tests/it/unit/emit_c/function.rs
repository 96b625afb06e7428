use dynamics_codegen::emit_c::functions;
use dynamics_codegen::emit_c::Precision;
use dynamics_codegen::method::{Family, FamilySet, Method};

/// A 2R arm in a description file, with friction (a method with a default body).
const ARM: &str = r#"
    name = "arm"
    gravity = [0, -9.81, 0]
    [[joints]]
    type = "revolute"
    a = 0.5
    mass = 2
    com = [-0.25, 0, 0]
    inertia = [0, 0.04, 0.04, 0, 0, 0]
    friction_viscous = 0.1
    [[joints]]
    type = "revolute"
    a = 0.4
    mass = 1
    com = [-0.2, 0, 0]
    inertia = [0, 0.01, 0.01, 0, 0, 0]
"#;

/// The equations of [`ARM`] with every family of a fixed base: every method of the table
/// but a floating base's (the C back end's tests).
pub(crate) fn arm_with_every_family() -> dynamics_codegen::trace::Equations {
    let robot = dynamics_codegen::front::from_toml(ARM, "arm").expect("a valid robot");
    let mut eq = dynamics_codegen::trace::derive(&robot);
    let every = Family::ALL
        .iter()
        .copied()
        .filter(|f| !f.is_floating())
        .fold(FamilySet::default(), FamilySet::with);
    eq.add_families(&robot, every);
    // The simplified family needs its request, which no family set carries.
    let joint =
        dynamics_codegen::front::default_envelope(dynamics_codegen::model::JointKind::Revolute);
    let request = dynamics_codegen::model::Simplification {
        tolerance: vec![0.01; 2],
        envelope: dynamics_codegen::model::Envelope {
            joints: vec![joint; 2],
        },
    };
    dynamics_codegen::simplify::add(&mut eq, &request).expect("simplifies");
    eq
}

/// With every family asked for, each method of the table has its two functions, in the
/// table's order: a new row gets its C function with no change to the C back end.
#[test]
fn every_method_of_the_table_has_a_function_in_each_precision() {
    let eq = arm_with_every_family();
    let names: Vec<String> = functions(&eq, "arm").into_iter().map(|f| f.name).collect();
    let expected: Vec<String> = Method::ALL
        .iter()
        .filter(|m| !m.family().is_floating())
        .flat_map(|m| Precision::ALL.map(|p| format!("arm_{}{}", m.name(), p.suffix())))
        .collect();
    assert_eq!(names, expected);
}

/// The header's promise that outputs may alias inputs: in every function, no line after
/// the first store into an output array reads an input array, the regressors' stores as
/// their values are computed included.
#[test]
fn every_input_is_read_before_the_first_store() {
    let eq = arm_with_every_family();
    for f in functions(&eq, "arm") {
        let inputs: Vec<String> = f
            .arguments
            .iter()
            .map(|(a, _)| a.name())
            .chain((f.parameters > 0).then_some("params"))
            .map(|a| format!("{a}["))
            .collect();
        let text = f.definition(&eq, "arm_sign");
        let stores: Vec<String> = f.outputs.iter().map(|a| format!("{}[", a.name)).collect();
        let body = text.lines().skip_while(|l| !l.starts_with("static inline"));
        let mut stored = false;
        for line in body.skip(1) {
            let line = line.trim_start();
            // The derivatives' second body (their tangents column by column) reads anew.
            if line.starts_with("#else") {
                stored = false;
            }
            let reads = |array: &str| {
                line.match_indices(array).any(|(i, _)| {
                    i == 0 || !line[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_')
                })
            };
            if stored {
                assert!(
                    !inputs.iter().any(|a| reads(a.as_str())),
                    "{}: `{line}` reads an input after a store",
                    f.name
                );
            }
            stored |= stores.iter().any(|a| line.starts_with(a.as_str()));
        }
        assert!(stored || f.outputs.is_empty(), "{} stores nothing", f.name);
    }
}

/// The names a function binds cannot meet: an output array or element (`m`, `m1_2`) is
/// never an argument (`q`, `tau`), a temporary (`t4`), a pivot (`d2`), a sine or cosine
/// (`s2`, `c2`), a parameter (`p_...`) or the solved stack's `value`.
#[test]
fn comments_are_ascii() {
    let table = [
        ("C(q, q̇) q̇ + g(q).", "C(q, qd) qd + g(q)."),
        ("q̈ = M(q)⁻¹ (τ − f(q̇)).", "qdd = M(q)^-1 (tau - f(qd))."),
        (
            "T = ᴴJᵀ ᴴF, ∂τ/∂q, A1 ⋯ An, Σ_k",
            "T = HJ^T HF, dtau/dq, A1 ... An, sum_k",
        ),
        ("a */ b ✓", "a * / b ?"),
    ];
    for (text, ascii) in table {
        assert_eq!(
            dynamics_codegen::emit_c::function::comment_safe(text),
            ascii
        );
    }
    for &m in Method::ALL {
        let summary = dynamics_codegen::emit_c::function::comment_safe(m.summary());
        assert!(!summary.contains('?'), "{m:?}: {summary}");
    }
}

#[test]
fn element_names_are_apart_from_every_other_local() {
    for &m in Method::ALL {
        let prefix = m.prefix();
        assert!(m.arguments().iter().all(|a| a.name() != prefix), "{m:?}");
        assert!(
            !["t", "d", "s", "c", "value", "params"].contains(&prefix),
            "{m:?}"
        );
        assert!(!prefix.starts_with("p_"), "{m:?}");
        // An element `tau3` would be the joint torque read by a method that takes `tau`.
        let takes_tau = m
            .arguments()
            .contains(&dynamics_codegen::method::Argument::Tau);
        assert!(!(takes_tau && prefix == "tau"), "{m:?}");
    }
}
