use dynamics_codegen::simplify::{max_abs_cos, max_abs_sin};
use std::f64::consts::PI;

/// The exact maximum, against a dense sampling that it must bound and nearly reach.
#[test]
fn the_largest_sine_and_cosine_over_an_interval() {
    let cases = [
        (0.0, 1.0),
        (-0.3, 0.2),
        (1.0, 2.0),
        (2.0, 3.0),
        (-PI, PI),
        (3.5, 4.0),
        (-7.0, -6.5),
        (10.0, 10.1),
    ];
    for (lo, hi) in cases {
        let samples = (0..=10_000).map(|k| lo + (hi - lo) * f64::from(k) / 10_000.0);
        let (s, c) = samples.fold((0.0f64, 0.0f64), |(s, c), x| {
            (s.max(x.sin().abs()), c.max(x.cos().abs()))
        });
        let (bs, bc) = (max_abs_sin(lo, hi), max_abs_cos(lo, hi));
        assert!(bs >= s && bs - s < 1e-6, "sin on [{lo}, {hi}]: {bs} vs {s}");
        assert!(bc >= c && bc - c < 1e-6, "cos on [{lo}, {hi}]: {bc} vs {c}");
    }
    assert_eq!(max_abs_sin(0.0, 1.0), (1.0f64.sin() + 1e-12));
    assert_eq!(max_abs_cos(-0.1, 0.1), 1.0);
}
