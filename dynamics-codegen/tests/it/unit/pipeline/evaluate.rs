use dynamics_codegen::pipeline::State;
use dynamics_codegen::pipeline::{load, Source};
use dynamics_codegen::FamilySet;

/// The Cartesian robot of one prismatic joint along the vertical: τ = m (q̈ + g) and
/// M = m, from a description alone (Niku's Example 6.1 in one dimension).
#[test]
fn a_falling_mass_at_one_state() {
    let text = "name = \"lift\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\n\
                type = \"prismatic\"\nmass = 2\ncom = [0, 0, 0]\n";
    let source = Source {
        path: "lift.toml",
        text: Some(text),
        ..Source::default()
    };
    let eq = load(&source)
        .expect("loads")
        .equations(FamilySet::default(), None)
        .expect("traces");
    let state = State {
        fields: &[],
        q: &[0.3],
        qd: &[1.5],
        qdd: &[0.5],
        tau: &[],
    };
    let values = eq.evaluate(&state);
    let tau = values.vector(&eq.tau);
    assert!((tau[0] - 2.0 * (0.5 + 9.81)).abs() < 1e-12, "{tau:?}");
    assert!((values.matrix(&eq.mass)[0][0] - 2.0).abs() < 1e-12);
}
