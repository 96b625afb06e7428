//! Two-step weighted least squares against the normal equations solved by hand.

use dynamics_identification::identify::estimate::{estimate, joint_sigmas, ITERATIONS, SETTLED};
use dynamics_identification::identify::measured::Measured;

/// Normal deviates from a fixed seed (xorshift64 and Box-Muller).
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform().max(1e-300), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// Two joints, parameters [a, b, c, d]: `τ1 = a x + b`, `τ2 = c y + d x² + b`, the noise
/// of joint 2 a hundred times joint 1's. Rows as the test builds them for its own solution.
fn rows(noise: &mut Noise) -> Vec<(usize, Vec<f64>, f64)> {
    let pi = [2.0, -1.0, 0.5, 3.0];
    let mut out = Vec::new();
    for k in 0..400 {
        let x = (f64::from(k) * 0.37).sin();
        let y = (f64::from(k) * 0.11).cos();
        let y1 = [x, 1.0, 0.0, 0.0];
        let y2 = [0.0, 1.0, y, x * x];
        let dot = |r: &[f64; 4]| r.iter().zip(pi).map(|(a, b)| a * b).sum::<f64>();
        out.push((0, y1.to_vec(), dot(&y1) + 0.01 * noise.normal()));
        out.push((1, y2.to_vec(), dot(&y2) + noise.normal()));
    }
    out
}

fn measured(rows: &[(usize, Vec<f64>, f64)]) -> Measured {
    let columns = vec![vec![0, 1], vec![1, 2, 3]];
    let mut m = Measured::new(columns.clone(), 4);
    for (i, row, tau) in rows {
        let own: Vec<f64> = columns[*i].iter().map(|&k| row[k]).collect();
        m.push(*i, &own, *tau);
    }
    m
}

/// `(Σ w² yᵀy)⁻¹` and the solution of the weighted normal equations, by Gauss-Jordan
/// elimination: the textbook route, independent of the factors.
fn normal_equations(rows: &[(usize, Vec<f64>, f64)], w: [f64; 2]) -> (Vec<f64>, Vec<Vec<f64>>) {
    let mut a = vec![vec![0.0; 9]; 4];
    for (i, y, tau) in rows {
        for r in 0..4 {
            for c in 0..4 {
                a[r][c] += w[*i] * w[*i] * y[r] * y[c];
            }
            a[r][8] += w[*i] * w[*i] * y[r] * tau;
        }
    }
    for (r, row) in a.iter_mut().enumerate() {
        row[4 + r] = 1.0;
    }
    for c in 0..4 {
        let pivot = a[c][c];
        a[c].iter_mut().for_each(|x| *x /= pivot);
        for r in (0..4).filter(|&r| r != c) {
            let f = a[r][c];
            let source = a[c].clone();
            a[r].iter_mut().zip(source).for_each(|(x, s)| *x -= f * s);
        }
    }
    let solution = a.iter().map(|row| row[8]).collect();
    (solution, a.iter().map(|row| row[4..8].to_vec()).collect())
}

#[test]
fn two_step_weighted_least_squares_as_the_normal_equations_give_it() {
    let rows = rows(&mut Noise(0x9e37_79b9_7f4a_7c15));
    let e = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
    // Step 1 by hand: the ordinary fit, then each joint's σ over N − c_i.
    let (ordinary, _) = normal_equations(&rows, [1.0, 1.0]);
    let sigma: Vec<f64> = [(0, 2.0), (1, 3.0)]
        .iter()
        .map(|&(i, c)| {
            let ss: f64 = rows
                .iter()
                .filter(|r| r.0 == i)
                .map(|(_, y, t)| {
                    (y.iter().zip(&ordinary).map(|(a, b)| a * b).sum::<f64>() - t).powi(2)
                })
                .sum();
            (ss / (400.0 - c)).sqrt()
        })
        .collect();
    for (got, want) in e.sigma.iter().zip(&sigma) {
        assert!((got - want).abs() < 1e-10 * want, "{:?} {sigma:?}", e.sigma);
    }
    // Step 2: weights 1/σ_i; the covariance σ̂² (YᵀWY)⁻¹ with σ̂² over nN − b.
    let (weighted, inverse) = normal_equations(&rows, [1.0 / sigma[0], 1.0 / sigma[1]]);
    let ss: f64 = rows
        .iter()
        .map(|(i, y, t)| {
            let r = y.iter().zip(&weighted).map(|(a, b)| a * b).sum::<f64>() - t;
            (r / sigma[*i]).powi(2)
        })
        .sum();
    let variance = ss / (800.0 - 4.0);
    for k in 0..4 {
        assert!((e.values[k] - weighted[k]).abs() < 1e-10, "{k}");
        let deviation = (variance * inverse[k][k]).sqrt();
        assert!(
            (e.deviations[k] - deviation).abs() < 1e-8 * deviation,
            "{k}"
        );
        // And the truth is within a few standard deviations.
        let truth = [2.0, -1.0, 0.5, 3.0][k];
        assert!(
            (e.values[k] - truth).abs() < 4.0 * deviation,
            "{k}: {}",
            e.values[k]
        );
    }
    assert!(e.weighted && e.unidentified.is_empty() && e.samples == 400);
}

/// Joint 1's torques are a hundred times less noisy than joint 2's, and share parameter b
/// with them: the ordinary fit's b carries joint 2's noise into joint 1's residual, so its
/// σ_1 is too large; iterated, σ_1 comes from the weighted fit, and the σ_i are a fixed
/// point: those of the final fit's own residuals, to the 1 % at which iteration stops.
#[test]
fn iterated_weights_come_from_the_weighted_fit() {
    let rows = rows(&mut Noise(0x9e37_79b9_7f4a_7c15));
    let once = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
    let mut m = measured(&rows);
    let e = estimate(&mut m, 1e-8, ITERATIONS).unwrap();
    assert!(
        e.reweighted > 0 && e.reweighted <= ITERATIONS,
        "{}",
        e.reweighted
    );
    let kept = [0, 1, 2, 3];
    let own = joint_sigmas(&mut m, &kept, &e.values, 400).unwrap();
    for (got, want) in e.sigma.iter().zip(&own) {
        assert!((got / want - 1.0).abs() < SETTLED, "{:?} {own:?}", e.sigma);
    }
    // Noise 0.01 put in joint 1: the iterated σ_1 nearer it than the ordinary fit's.
    let error = |s: f64| (s / 0.01 - 1.0).abs();
    assert!(
        error(e.sigma[0]) < error(once.sigma[0]),
        "{} {}",
        e.sigma[0],
        once.sigma[0]
    );
    assert!(error(e.sigma[0]) < 0.1, "{:?} {:?}", e.sigma, once.sigma);
}

#[test]
fn exact_data_are_fitted_exactly() {
    let rows: Vec<_> = rows(&mut Noise(1))
        .into_iter()
        .map(|(i, y, _)| {
            let tau = y
                .iter()
                .zip([2.0, -1.0, 0.5, 3.0])
                .map(|(a, b)| a * b)
                .sum();
            (i, y, tau)
        })
        .collect();
    let e = estimate(&mut measured(&rows), 1e-8, 0).unwrap();
    for (got, want) in e.values.iter().zip([2.0, -1.0, 0.5, 3.0]) {
        assert!((got - want).abs() < 1e-12, "{:?}", e.values);
    }
    assert!(e.rms.iter().all(|&r| r < 1e-12), "{:?}", e.rms);
    assert!(e.condition > 1.0 && e.condition.is_finite());
}
