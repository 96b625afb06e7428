//! Struct fields whose names are Rust keywords (`r#type`, `r#loop`): the values name them with
//! or without `r#`, and the generated code reads them as raw identifiers.

use dynamics_runtime::Dynamics;

/// A pendulum: a point mass `type` at the tip of a link of length `loop`, gravity along −y.
/// By hand: M = m l², g(q) = 9.81 m l cos q.
#[derive(Dynamics)]
#[dynamics(gravity = [0, -9.81, 0], dh = [[q, 0, r#loop, 0]], link(mass = self.type))]
struct Keyworded {
    r#type: f64,
    r#loop: f64,
}

#[test]
fn keyword_fields_are_read_raw() {
    let arm = Keyworded {
        r#type: 3.0,
        r#loop: 2.0,
    };
    // M = 3 · 2² = 12 whatever q; g(0) = 9.81 · 3 · 2 = 58.86.
    assert_eq!(arm.mass_matrix::<f64>(&[0.7]), [[12.0]]);
    let g = arm.gravity_torques::<f64>(&[0.0])[0];
    assert!((g - 58.86).abs() < 1e-12, "{g}");
}
