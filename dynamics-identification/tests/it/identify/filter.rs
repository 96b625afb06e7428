//! The zero-phase Butterworth low-pass: SciPy's coefficients, its gain, its ends.

use dynamics_identification::identify::filter::{LowPass, ORDER};
use std::f64::consts::PI;

/// The transfer function's numerator and denominator, highest power of `z⁻¹` last.
fn polynomials(filter: &LowPass) -> (Vec<f64>, Vec<f64>) {
    let multiply = |p: &[f64], q: &[f64]| {
        let mut r = vec![0.0; p.len() + q.len() - 1];
        for (i, a) in p.iter().enumerate() {
            for (j, b) in q.iter().enumerate() {
                r[i + j] += a * b;
            }
        }
        r
    };
    let (mut b, mut a) = (vec![1.0], vec![1.0]);
    for &[b0, b1, b2, a1, a2] in filter.sections() {
        b = multiply(&b, &[b0, b1, b2]);
        a = multiply(&a, &[1.0, a1, a2]);
    }
    (b, a)
}

/// `scipy.signal.butter(4, 50 / 500)` (SciPy 1.17.1): 50 Hz at 1 kHz.
#[test]
fn the_coefficients_are_scipys() {
    let (b, a) = polynomials(&LowPass::butterworth(50.0, 1000.0).unwrap());
    let scipy_b = [
        0.000_416_599_204_406_6,
        0.001_666_396_817_626_4,
        0.002_499_595_226_439_6,
        0.001_666_396_817_626_4,
        0.000_416_599_204_406_6,
    ];
    let scipy_a = [
        1.0,
        -3.180_638_548_874_719,
        3.861_194_348_994_213_3,
        -2.112_155_355_110_969,
        0.438_265_142_261_979_77,
    ];
    for (got, want) in b.iter().chain(&a).zip(scipy_b.iter().chain(&scipy_a)) {
        assert!((got - want).abs() < 1e-15, "{b:?} {a:?}");
    }
}

/// A sinusoid comes out scaled by `|H|² = 1 / (1 + (tan(ω/2) / K)^8)` and not shifted.
#[test]
fn forward_and_backward_is_the_squared_magnitude_without_phase() {
    let (rate, cutoff) = (1000.0, 40.0);
    let filter = LowPass::butterworth(cutoff, rate).unwrap();
    let k = (PI * cutoff / rate).tan();
    for f in [5.0, 40.0, 60.0] {
        let w = 2.0 * PI * f / rate;
        let mut x: Vec<f64> = (0..4000).map(|i| 3.0 + (w * f64::from(i)).sin()).collect();
        filter.filtfilt(&mut x);
        let gain = 1.0 / (1.0 + ((w / 2.0).tan() / k).powi(2 * ORDER as i32));
        // Away from the ends, where the padding's guess is forgotten.
        for i in 1000..3000u32 {
            let want = 3.0 + gain * (w * f64::from(i)).sin();
            let got = x[i as usize];
            assert!((got - want).abs() < 1e-9, "{f} Hz at {i}: {got} {want}");
        }
    }
}

#[test]
fn constants_stay_exact_and_slow_ramps_pass_to_the_ends() {
    let filter = LowPass::butterworth(10.0, 500.0).unwrap();
    let mut constant = vec![0.300_000_000_000_000_1; 50];
    filter.filtfilt(&mut constant);
    assert!(constant.iter().all(|&v| v == 0.300_000_000_000_000_1));
    // The odd extension continues a line as a line, and the two passes' delays cancel: a
    // ramp passes, ends included, but for what is left of the padding's start (a lag of 21
    // samples, 0.2, forgotten to e^{−10}).
    let mut ramp: Vec<f64> = (0..300).map(|i| 1.0 + 0.01 * f64::from(i)).collect();
    filter.filtfilt(&mut ramp);
    for (i, v) in ramp.iter().enumerate() {
        assert!((v - (1.0 + 0.01 * i as f64)).abs() < 2e-5, "{i}: {v}");
    }
    assert!(LowPass::butterworth(250.0, 500.0).is_err());
}
