//! The Fourier series of an exciting motion: its derivatives, at rest, fitted into limits.

use dynamics_identification::excite::fourier::{Grid, Limits, Series, State};

fn grid() -> Grid {
    Grid::new(10.0, 4, 1000)
}

/// The derivatives against central differences of the positions, and the formula at an
/// arbitrary time evaluated directly (not from the table).
#[test]
fn the_state_is_the_series_and_its_derivatives() {
    let g = grid();
    let series = Series {
        q0: 0.3,
        a: vec![0.2, -0.1, 0.05, 0.3],
        b: vec![-0.4, 0.25, 0.1, -0.05],
    };
    let h = g.period / g.samples() as f64;
    for k in [1, 137, 500, 999] {
        let (before, now, after) = (
            g.state(&series, k - 1),
            g.state(&series, k),
            g.state(&series, k + 1),
        );
        assert!(
            (now.qd - (after.q - before.q) / (2.0 * h)).abs() < 1e-3,
            "{k}"
        );
        assert!(
            (now.qdd - (after.qd - before.qd) / (2.0 * h)).abs() < 1e-3,
            "{k}"
        );
        let t = k as f64 * h;
        let direct: f64 = (1..=4)
            .map(|l| {
                let w = g.omega() * f64::from(l);
                let (a, b) = (series.a[l as usize - 1], series.b[l as usize - 1]);
                (a * (w * t).sin() - b * (w * t).cos()) / w
            })
            .sum();
        assert!((now.q - 0.3 - direct).abs() < 1e-12, "{k}");
    }
    // Periodic, bit for bit.
    assert_eq!(g.state(&series, 17), g.state(&series, 17 + 3 * 1000));
}

#[test]
fn the_series_at_rest_starts_at_rest() {
    let g = grid();
    let series = g.at_rest(&[0.3, -0.2, 0.5, 0.1, 0.4, -0.7]);
    assert_eq!((series.a.len(), series.b.len()), (4, 4));
    let s = g.state(&series, 0);
    assert_eq!((s.qd, s.qdd), (0.0, 0.0));
    let limits = limit_of(1.0);
    let fitted = g
        .fit(&[0.3, -0.2, 0.5, 0.1, 0.4, -0.7], &limits, 0.2)
        .expect("moves");
    for k in [0, 1000, 7000] {
        let s = g.state(&fitted, k);
        assert_eq!((s.qd, s.qdd), (0.0, 0.0), "{k}");
    }
    assert_eq!(&series.a[1..], [0.3, -0.2, 0.5]);
    assert_eq!(&series.b[1..], [0.1, 0.4, -0.7]);
}

/// Each limit in turn binds: the motion then reaches it (to the margin) and stays within
/// the others at every sample.
#[test]
fn the_fit_reaches_the_binding_limit_and_keeps_the_others() {
    let g = grid();
    let shape = [0.3, -0.2, 0.5, 0.1, 0.4, -0.7];
    let cases = [
        (-0.5, 1.0, 100.0, 100.0),
        (-10.0, 10.0, 0.7, 100.0),
        (-10.0, 10.0, 100.0, 2.0),
    ];
    for (case, &(lower, upper, velocity, acceleration)) in cases.iter().enumerate() {
        let limits = Limits {
            lower,
            upper,
            velocity,
            acceleration,
        };
        for placement in [-1.0, 0.0, 0.4, 1.0, 3.0] {
            let fitted = g.fit(&shape, &limits, placement).expect("it moves");
            let states: Vec<State> = (0..g.samples()).map(|k| g.state(&fitted, k)).collect();
            let low = states.iter().map(|s| s.q).fold(f64::MAX, f64::min);
            let high = states.iter().map(|s| s.q).fold(f64::MIN, f64::max);
            let speed = states.iter().map(|s| s.qd.abs()).fold(0.0, f64::max);
            let acc = states.iter().map(|s| s.qdd.abs()).fold(0.0, f64::max);
            assert!(low >= lower && high <= upper, "{case} {placement}");
            assert!(
                speed <= velocity && acc <= acceleration,
                "{case} {placement}"
            );
            let reached = [
                (high - low) / (upper - lower),
                speed / velocity,
                acc / acceleration,
            ];
            assert!((reached[case] - 1.0).abs() < 1e-8, "{case}: {reached:?}");
            // The placement: at the lower limit, centred, at the upper.
            let slack = (upper - lower) - (high - low);
            let at = match placement {
                p if p <= -1.0 => low - lower,
                p if p >= 1.0 => upper - high,
                _ => (low - lower) - 0.5 * (1.0 + placement) * slack,
            };
            assert!(
                at.abs() < 1e-8 * (upper - lower),
                "{case} {placement}: {at}"
            );
        }
    }
    assert!(g.fit(&[0.0; 6], &limit_of(1.0), 0.0).is_none());
}

fn limit_of(x: f64) -> Limits {
    Limits {
        lower: -x,
        upper: x,
        velocity: x,
        acceleration: x,
    }
}
