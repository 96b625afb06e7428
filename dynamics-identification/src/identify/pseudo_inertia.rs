//! A link's pseudo-inertia `J = [[½ tr(I) 1 − I, h], [hᵀ, m]]` (`h = m c`, I about the link
//! frame's origin): its parameters are those of a mass distribution exactly when `J ⪰ 0`
//! (Wensing, Kim and Slotine 2017). Its eigenvalues (nalgebra's), and the nearest positive
//! semidefinite J.

use crate::linear_algebra::eigen4;

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

/// `x` with each link's J replaced by its nearest positive semidefinite matrix (negative
/// eigenvalues, above the cuts' tolerance, set to zero), so that the parameters written to a
/// description pass its checks (a mass not below zero, the triangle inequality to 10⁻⁹).
pub(super) fn clipped(mut x: Vec<f64>, links: usize) -> Vec<f64> {
    for l in 0..links {
        let pi = &mut x[10 * l..10 * l + 10];
        let (values, vectors) = eigen4(pseudo_inertia(pi));
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
    eigen4(pseudo_inertia(pi))
        .0
        .into_iter()
        .fold(f64::INFINITY, f64::min)
}
