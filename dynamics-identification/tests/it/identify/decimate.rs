//! The decimation's low-pass and the rows it keeps.

use dynamics_identification::identify::decimate::{taps, Decimator, OPEN};
use std::f64::consts::PI;

/// The filter's gain at `f` cycles per sample.
fn gain(taps: &[f64], f: f64) -> f64 {
    let m = (taps.len() / 2) as f64;
    taps.iter()
        .enumerate()
        .map(|(i, h)| h * (2.0 * PI * f * (i as f64 - m)).cos())
        .sum()
}

#[test]
fn the_low_pass_passes_below_the_kept_nyquist_and_stops_above() {
    for d in [1, 4, 20] {
        let h = taps(d);
        assert_eq!(h.len(), 16 * d + 1);
        assert!((h.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        let nyquist = 0.5 / d as f64;
        if d > 1 {
            // Within 0.4 % of 1 to 0.75 of the cutoff, half at it, 47 dB down past 1.2 of it.
            for f in [0.0, 0.25, 0.5, 0.7, 0.75] {
                assert!((gain(&h, f * nyquist) - 1.0).abs() < 4e-3, "{d} {f}");
            }
            assert!((gain(&h, nyquist) - 0.5).abs() < 0.01, "{d}");
            for f in [1.2, 1.25, 1.5, 2.0, 3.0] {
                assert!(gain(&h, f * nyquist).abs() < 4.5e-3, "{d} {f}");
            }
        } else {
            // d = 1: the ideal low-pass at the Nyquist frequency is the identity.
            assert!((h[8] - 1.0).abs() < 1e-15);
        }
    }
}

#[test]
fn rows_are_filtered_alike_and_one_in_d_is_kept_at_the_window_middle() {
    let d = 3;
    let mut decimator = Decimator::new(d, 2);
    let mut kept = Vec::new();
    for k in 0..200 {
        let t = f64::from(k);
        // A slow sinusoid passes unshifted (zero phase); a constant passes unchanged.
        let row = [(2.0 * PI * 0.02 * t).sin(), 5.0];
        if let Some((t, out)) = decimator.push(t, &row) {
            kept.push((t, out.to_vec()));
        }
    }
    // Windows of 49 rows: the first complete at row 48, middle 24; then every third.
    assert_eq!(kept.len(), (200 - 49) / 3 + 1);
    assert_eq!(kept[0].0, 24.0);
    assert_eq!(kept[1].0, 27.0);
    for (t, out) in &kept {
        let want = gain(&taps(d), 0.02) * (2.0 * PI * 0.02 * t).sin();
        assert!((out[0] - want).abs() < 1e-12, "{t}");
        assert!((out[1] - 5.0).abs() < 1e-12);
    }
}

/// Each output is its window's weighted sum, summed oldest row first, and the memory held
/// is 17 rows whatever the decimation.
#[test]
fn outputs_are_their_windows_sums_with_seventeen_rows_held() {
    for d in [1, 2, 5] {
        let x: Vec<f64> = (0..300)
            .map(|k| (0.37 * f64::from(k)).sin() + 0.1)
            .collect();
        let h = taps(d);
        let mut decimator = Decimator::new(d, 1);
        assert_eq!(decimator.held(), OPEN);
        let mut outputs = Vec::new();
        for (k, v) in x.iter().enumerate() {
            if let Some((t, out)) = decimator.push(k as f64, &[*v]) {
                outputs.push((t, out[0]));
            }
        }
        let windows: Vec<(f64, f64)> = (0..=(x.len() - h.len()) / d)
            .map(|m| {
                let window = &x[m * d..m * d + h.len()];
                let sum = h.iter().zip(window).fold(0.0, |s, (a, b)| s + a * b);
                ((m * d + 8 * d) as f64, sum)
            })
            .collect();
        assert_eq!(outputs, windows, "{d}");
    }
    assert_eq!(Decimator::new(1000, 3).held(), 3 * OPEN);
}
