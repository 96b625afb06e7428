//! `identify --consistent --description-out FILE.toml`: the robot's TOML description with the
//! consistent estimate's values in place of its own, everything else (comments, layout, keys)
//! kept, so that `dynamics` and `#[dynamics(file = ..)]` read it back.
//!
//! A link's standard parameters become the description's `mass`, `com` and `inertia` about the
//! centre of mass ([`about_com`], which keeps round-off from reading as a body that cannot be).
//! Its `check_inertia = false`, if any, is removed: the values pass the checks. The joint terms
//! estimated replace `actuator_inertia` (and a `rotor_inertia`, `gear_ratio` pair),
//! `friction_viscous`, `friction_coulomb`, `friction_offset`.

use dynamics_codegen::Parameter;
use dynamics_identification::identify::about_com::about_com;
use toml_edit::{value, Array, DocumentMut};

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
