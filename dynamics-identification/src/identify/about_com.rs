//! A link's standard parameters `[m, h, I_o]` (about the link frame's origin, as the regressor
//! has them) as a description gives a body: mass `m`, centre of mass `c = h / m` and inertia
//! about the centre of mass, `I_c = I_o − m (|c|² 1 − c cᵀ)` (`Ixx_c = Ixx − m (cy² + cz²)`,
//! `Ixy_c = Ixy + m cx cy`, entries `−∫xy dm`), written `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`: for
//! the description file of `identify --consistent --description-out`.
//!
//! **Round-off.** `I_c` is the difference of `I_o` and the parallel-axis term, which are nearly
//! equal for a link whose mass is nearly a point or a line (the consistent estimate often puts
//! a poorly excited link on the edge of the cone `J ⪰ 0`): its entries then hold the round-off
//! of that difference, `ε m |c|²`, whose sign the description's checks, relative to the
//! tensor's own size, would read as a tensor no body has. So `I_c` is computed from the second
//! moment about the centre of mass, `Σ_c = Σ_o − h hᵀ / m` (`Σ_o = ½ tr(I_o) 1 − I_o`), whose
//! eigenvalues below [`ROUND_OFF`] of `tr Σ_o = ∫|r|² dm` (round-off of zero, or negative) are
//! set to zero: `I_c = tr(Σ_c) 1 − Σ_c` is then positive semidefinite with principal moments
//! `s_j + s_k` (s the eigenvalues of `Σ_c`), which meet the triangle inequality, exactly at its
//! edge for a lamina or a rod and as a zero tensor for a point mass. Likewise a mass below
//! [`ROUND_OFF`] of the largest entry of the link's pseudo-inertia is zero, with `c = 0` and
//! `I_c = I_o` (J ⪰ 0 bounds `|h|² ≤ m tr Σ_o`: such a link's `h` is round-off too).

use super::pseudo_inertia::pseudo_inertia;
use crate::linear_algebra::eigen3;

/// A value below this fraction of the quantities it is computed from is round-off of zero.
pub const ROUND_OFF: f64 = 1e-12;

/// Mass, centre of mass and inertia about it of a link's ten standard parameters.
#[must_use]
pub fn about_com(pi: &[f64]) -> (f64, [f64; 3], [f64; 6]) {
    let j = pseudo_inertia(pi);
    let largest = j.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
    let m = pi[0];
    let mut sigma: [[f64; 3]; 3] = std::array::from_fn(|a| std::array::from_fn(|b| j[a][b]));
    let (mass, com) = if m > ROUND_OFF * largest {
        let c = [pi[1] / m, pi[2] / m, pi[3] / m];
        for (a, row) in sigma.iter_mut().enumerate() {
            for (b, x) in row.iter_mut().enumerate() {
                *x -= pi[1 + a] * c[b];
            }
        }
        (m, c)
    } else {
        (0.0, [0.0; 3])
    };
    let floor = ROUND_OFF * (j[0][0] + j[1][1] + j[2][2]).max(0.0);
    let s = second_moment(sigma, floor);
    let trace = s[0][0] + s[1][1] + s[2][2];
    let inertia = [
        trace - s[0][0],
        trace - s[1][1],
        trace - s[2][2],
        -s[0][1],
        -s[0][2],
        -s[1][2],
    ];
    (mass, com, inertia)
}

/// The symmetric `sigma` with its eigenvalues below `floor` set to zero (itself if there are
/// none).
fn second_moment(sigma: [[f64; 3]; 3], floor: f64) -> [[f64; 3]; 3] {
    let (values, vectors) = eigen3(sigma);
    if values.iter().all(|&v| v > floor) {
        return sigma;
    }
    std::array::from_fn(|a| {
        std::array::from_fn(|b| {
            (0..3)
                .filter(|&k| values[k] > floor)
                .map(|k| values[k] * vectors[k][a] * vectors[k][b])
                .sum()
        })
    })
}
