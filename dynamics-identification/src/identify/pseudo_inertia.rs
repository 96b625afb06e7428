//! A link's pseudo-inertia `J = [[½ tr(I) 1 − I, h], [hᵀ, m]]` (`h = m c`, I about the link
//! frame's origin): its parameters are those of a mass distribution exactly when `J ⪰ 0`
//! (Wensing, Kim and Slotine 2017). Its eigenvalues by Jacobi rotations, and the nearest
//! positive semidefinite J.

/// `J = [[½ tr(I) 1 − I, h], [hᵀ, m]]` of a link's ten parameters.
#[must_use]
pub fn pseudo_inertia(pi: &[f64]) -> [[f64; 4]; 4] {
    let [m, hx, hy, hz, xx, xy, yy, xz, yz, zz] = [
        pi[0], pi[1], pi[2], pi[3], pi[4], pi[5], pi[6], pi[7], pi[8], pi[9],
    ];
    let half = 0.5 * (xx + yy + zz);
    [
        [half - xx, -xy, -xz, hx],
        [-xy, half - yy, -yz, hy],
        [-xz, -yz, half - zz, hz],
        [hx, hy, hz, m],
    ]
}

/// The eigenvalues of a symmetric 4 × 4 matrix and their unit eigenvectors, by cyclic Jacobi
/// rotations (each zeroes one off-diagonal pair; sweeps until the off-diagonal part is
/// negligible).
#[must_use]
pub fn eigen(mut a: [[f64; 4]; 4]) -> ([f64; 4], [[f64; 4]; 4]) {
    let mut v = [[0.0; 4]; 4];
    for (i, row) in v.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for _ in 0..50 {
        let off: f64 = (0..4)
            .flat_map(|i| (0..4).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        let diagonal: f64 = (0..4).map(|i| a[i][i] * a[i][i]).sum();
        if off <= 1e-32 * diagonal || off == 0.0 {
            break;
        }
        for p in 0..3 {
            for q in p + 1..4 {
                if a[p][q] == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                // The smaller root of t² + 2θt − 1 = 0 (signum(0) = 1: a 45° turn).
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for row in &mut a {
                    let (akp, akq) = (row[p], row[q]);
                    row[p] = c * akp - s * akq;
                    row[q] = s * akp + c * akq;
                }
                let (rp, rq) = (a[p], a[q]);
                a[p] = std::array::from_fn(|k| c * rp[k] - s * rq[k]);
                a[q] = std::array::from_fn(|k| s * rp[k] + c * rq[k]);
                for row in &mut v {
                    let (vp, vq) = (row[p], row[q]);
                    row[p] = c * vp - s * vq;
                    row[q] = s * vp + c * vq;
                }
            }
        }
    }
    let values = [a[0][0], a[1][1], a[2][2], a[3][3]];
    let vectors = [0, 1, 2, 3].map(|k| [v[0][k], v[1][k], v[2][k], v[3][k]]);
    (values, vectors)
}

/// `x` with each link's J replaced by its nearest positive semidefinite matrix (negative
/// eigenvalues, above the cuts' tolerance, set to zero), so that the parameters written to a
/// description pass its checks (a mass not below zero, the triangle inequality to 10⁻⁹).
pub(super) fn clipped(mut x: Vec<f64>, links: usize) -> Vec<f64> {
    for l in 0..links {
        let pi = &mut x[10 * l..10 * l + 10];
        let (values, vectors) = eigen(pseudo_inertia(pi));
        if values.iter().all(|&v| v >= 0.0) {
            continue;
        }
        let j: [[f64; 4]; 4] = std::array::from_fn(|a| {
            std::array::from_fn(|b| {
                let terms = values.iter().zip(&vectors);
                terms.map(|(v, e)| v.max(0.0) * e[a] * e[b]).sum()
            })
        });
        // J's entries back to π: m, h, and I = tr(Σ) 1 − Σ.
        let trace = j[0][0] + j[1][1] + j[2][2];
        pi.copy_from_slice(&[
            j[3][3],
            j[0][3],
            j[1][3],
            j[2][3],
            trace - j[0][0],
            -j[0][1],
            trace - j[1][1],
            -j[0][2],
            -j[1][2],
            trace - j[2][2],
        ]);
    }
    x
}

/// The smallest eigenvalue of a link's pseudo-inertia.
#[must_use]
pub fn smallest_eigenvalue(pi: &[f64]) -> f64 {
    eigen(pseudo_inertia(pi))
        .0
        .into_iter()
        .fold(f64::INFINITY, f64::min)
}
