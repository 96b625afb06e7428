//! `identify --consistent --description-out FILE.toml`: the robot's TOML description with the
//! consistent estimate's values in place of its own, everything else (comments, layout, keys)
//! kept, so that `dynamics` and `#[dynamics(file = ..)]` read it back.
//!
//! A link's standard parameters `[m, h, I_o]` (about the link frame's origin) become the
//! description's mass `m`, centre of mass `c = h / m` and inertia about the centre of mass,
//! `I_c = I_o − m (|c|² 1 − c cᵀ)` (`Ixx_c = Ixx − m (cy² + cz²)`, `Ixy_c = Ixy + m cx cy`,
//! entries `−∫xy dm`), written `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`. Its `check_inertia = false`,
//! if any, is removed: the values pass the checks. The joint terms estimated replace
//! `actuator_inertia` (and a `rotor_inertia`, `gear_ratio` pair), `friction_viscous`,
//! `friction_coulomb`, `friction_offset`.
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

use dynamics_codegen::Parameter;
use dynamics_identification::identify::pseudo_inertia::pseudo_inertia;
use dynamics_identification::linear_algebra::eigen3;
use toml_edit::{value, Array, DocumentMut};

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

/// `text` (a TOML description) with the standard parameters `values` (`parameters`' order)
/// written into its joints.
///
/// # Errors
/// The text is not TOML, or its joints are not the robot's.
pub fn rewrite(text: &str, parameters: &[Parameter], values: &[f64]) -> Result<String, String> {
    let mut doc: DocumentMut = text.parse().map_err(|e| format!("{e}"))?;
    let joints = doc
        .get_mut("joints")
        .and_then(|j| j.as_array_of_tables_mut())
        .ok_or("the description has no [[joints]] tables")?;
    let array = |xs: &[f64]| value(xs.iter().copied().collect::<Array>());
    let links = parameters
        .iter()
        .filter(|p| matches!(p, Parameter::Link { index: 0, .. }))
        .count();
    if joints.len() != links {
        return Err(format!(
            "the description has {} [[joints]], the robot {links}",
            joints.len()
        ));
    }
    for (l, table) in joints.iter_mut().enumerate() {
        let (mass, com, inertia) = about_com(&values[10 * l..10 * l + 10]);
        table["mass"] = value(mass);
        table["com"] = array(&com);
        table["inertia"] = array(&inertia);
        table.remove("check_inertia");
    }
    for (p, &x) in parameters.iter().zip(values) {
        let Parameter::Joint { joint, index } = *p else {
            continue;
        };
        let table = joints.get_mut(joint).ok_or("a joint term of no joint")?;
        if index == 0 {
            table.remove("rotor_inertia");
            table.remove("gear_ratio");
        }
        let key = [
            "actuator_inertia",
            "friction_viscous",
            "friction_coulomb",
            "friction_offset",
        ][index];
        table[key] = value(x);
    }
    Ok(doc.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parallel_axis_theorem_undoes_the_shift_to_the_origin() {
        // A 2 kg body at c = (0.1, −0.2, 0.3) with a full inertia about its centre, moved to
        // the origin as the regressor's parameters have it (I_o = I_c + m (|c|² 1 − c cᵀ)).
        let (m, c) = (2.0, [0.1, -0.2, 0.3]);
        let ic = [0.05, 0.04, 0.03, 0.001, -0.002, 0.003];
        let shift = |a: usize, b: usize| {
            let delta = if a == b {
                c.iter().map(|x| x * x).sum()
            } else {
                0.0
            };
            m * (delta - c[a] * c[b])
        };
        let pi = [
            m,
            m * c[0],
            m * c[1],
            m * c[2],
            ic[0] + shift(0, 0),
            ic[3] + shift(0, 1),
            ic[1] + shift(1, 1),
            ic[4] + shift(0, 2),
            ic[5] + shift(1, 2),
            ic[2] + shift(2, 2),
        ];
        let (mass, com, inertia) = about_com(&pi);
        assert!((mass - m).abs() < 1e-15);
        for k in 0..3 {
            assert!((com[k] - c[k]).abs() < 1e-15, "{com:?}");
        }
        for k in 0..6 {
            assert!((inertia[k] - ic[k]).abs() < 1e-15, "{inertia:?}");
        }
    }

    /// A link's ten standard parameters: mass `m` with centre of mass `c` and second moment
    /// about it `sigma_c`, about the link frame's origin, in `f64` as the estimate has them.
    fn standard(m: f64, c: [f64; 3], sigma_c: [[f64; 3]; 3]) -> [f64; 10] {
        let h = c.map(|x| m * x);
        let s: [[f64; 3]; 3] =
            std::array::from_fn(|a| std::array::from_fn(|b| sigma_c[a][b] + h[a] * c[b]));
        let trace = s[0][0] + s[1][1] + s[2][2];
        [
            m,
            h[0],
            h[1],
            h[2],
            trace - s[0][0],
            -s[0][1],
            trace - s[1][1],
            -s[0][2],
            -s[1][2],
            trace - s[2][2],
        ]
    }

    /// Links on the edge of the cone J ⪰ 0, as the consistent estimate leaves poorly excited
    /// ones: point masses (`I_c = 0`), rods (`0 + I = I`), laminas and massless links with a
    /// mass of round-off; each written into a description that the description's own checks
    /// (the front door's, as `dynamics inspect` and the derive run them) must pass.
    #[test]
    fn links_on_the_edge_are_written_as_bodies_the_checks_accept() {
        let text =
            "name = \"one\"\ngravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n";
        let parameters: Vec<Parameter> = (0..10)
            .map(|index| Parameter::Link { link: 0, index })
            .collect();
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut failures = Vec::new();
        for case in 0..400 {
            let m = 0.05 + 2.0 * (uniform() + 0.5);
            let c = [uniform(), uniform(), uniform()].map(|x| 0.4 * x);
            // A unit direction, and a second one across it.
            let u = [uniform(), uniform(), uniform()];
            let norm = u.iter().map(|x| x * x).sum::<f64>().sqrt();
            let u = u.map(|x| x / norm);
            let w = [u[1], -u[0], 0.0];
            let wn = (w[0] * w[0] + w[1] * w[1]).sqrt();
            let w = w.map(|x| x / wn);
            let outer = |v: [f64; 3], k: f64| -> [[f64; 3]; 3] {
                std::array::from_fn(|a| std::array::from_fn(|b| k * v[a] * v[b]))
            };
            let add = |p: [[f64; 3]; 3], q: [[f64; 3]; 3]| -> [[f64; 3]; 3] {
                std::array::from_fn(|a| std::array::from_fn(|b| p[a][b] + q[a][b]))
            };
            let pi = match case % 4 {
                0 => standard(m, c, [[0.0; 3]; 3]),
                1 => standard(m, c, outer(u, 1e-3 * m)),
                2 => standard(m, c, add(outer(u, 1e-3 * m), outer(w, 4e-4 * m))),
                _ => {
                    // A massless lamina whose mass and first moment are round-off.
                    let mut pi = standard(0.0, c, add(outer(u, 1e-3), outer(w, 4e-4)));
                    (pi[0], pi[1]) = (-1e-19, 3e-20);
                    pi
                }
            };
            let out = rewrite(text, &parameters, &pi).expect("rewrites");
            let source = dynamics_codegen::Source {
                path: "one.toml",
                text: Some(&out),
                ..dynamics_codegen::Source::default()
            };
            if let Err(problems) = dynamics_codegen::load(&source) {
                failures.push(format!("case {case}: {}\n{out}", problems[0]));
            }
            let (written, _, inertia) = about_com(&pi);
            assert!(written >= 0.0);
            if case % 4 == 0 {
                // A point mass has no inertia about its centre: zeros, not round-off.
                assert_eq!(inertia, [0.0; 6], "case {case}");
            }
        }
        assert!(
            failures.is_empty(),
            "{} of 400: {}",
            failures.len(),
            failures[0]
        );
    }
}
