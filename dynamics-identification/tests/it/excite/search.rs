//! The search: its random deviates, the compass search, the budget of evaluations.

use dynamics_identification::excite::search::{minimise, Random, SMALLEST_STEP};

#[test]
fn the_deviates_are_uniform_and_the_seed_decides_them() {
    let mut r = Random::new(7);
    let draws: Vec<f64> = (0..20_000).map(|_| r.symmetric()).collect();
    assert!(draws.iter().all(|x| (-1.0..1.0).contains(x)));
    let mean = draws.iter().sum::<f64>() / draws.len() as f64;
    // Uniform on [−1, 1): mean 0, variance 1/3; the mean of 20,000 within 4 of its σ.
    assert!(
        mean.abs() < 4.0 * (1.0 / 3.0 / 20_000.0f64).sqrt(),
        "{mean}"
    );
    let below = draws.iter().filter(|x| **x < -0.5).count() as f64 / 20_000.0;
    assert!((below - 0.25).abs() < 0.015, "{below}");
    let again: Vec<f64> = {
        let mut r = Random::new(7);
        (0..20).map(|_| r.symmetric()).collect()
    };
    assert_eq!(again, draws[..20]);
    assert_ne!(Random::new(8).symmetric(), draws[0]);
    assert!(Random::new(0).symmetric().is_finite());
}

/// A shifted quadratic with its minimum inside the box, and one with its minimum outside
/// (at the box's corner after clamping).
#[test]
fn the_compass_search_finds_a_quadratic_s_minimum() {
    let centre = [0.3, -0.62, 0.05, 0.9];
    let f = |x: &[f64]| -> f64 {
        x.iter()
            .zip(centre)
            .enumerate()
            .map(|(i, (a, c))| (i + 1) as f64 * (a - c).powi(2))
            .sum()
    };
    let out = minimise(4, 3, 2000, f);
    assert!(out.step < SMALLEST_STEP, "converged: {out:?}");
    for (x, c) in out.best.0.iter().zip(centre) {
        assert!((x - c).abs() < 2.0 * SMALLEST_STEP, "{out:?}");
    }
    assert!(out.best.1 < out.initial.1);
    assert_eq!(out.restarts, 500);
    let corner = minimise(2, 3, 2000, |x: &[f64]| {
        (x[0] - 2.0).powi(2) + (x[1] + 3.0).powi(2)
    });
    assert_eq!(corner.best.0, [1.0, -1.0]);
}

#[test]
fn the_budget_is_kept_and_the_seed_decides_the_result() {
    let mut count = 0;
    let wavy = |x: &[f64]| x.iter().map(|a| (5.0 * a).sin() + a * a).sum::<f64>();
    let out = minimise(6, 11, 100, |x| {
        count += 1;
        wavy(x)
    });
    assert_eq!(count, 100);
    assert_eq!(out.restarts + out.compass, 100);
    let again = minimise(6, 11, 100, wavy);
    assert_eq!(again.best, out.best);
    assert_ne!(minimise(6, 12, 100, wavy).initial, out.initial);
}
