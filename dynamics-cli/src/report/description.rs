//! `identify --consistent --description-out FILE.toml`: the robot's TOML description with the
//! consistent estimate's values in place of its own, everything else (comments, layout, keys)
//! kept, so that `dynamics` and `#[dynamics(file = ..)]` read it back.
//!
//! A link's standard parameters become the description's `mass`, `com` and `inertia` about the
//! centre of mass ([`about_com`], which keeps round-off from reading as a body that cannot be).
//! Its `check_inertia = false`, if any, is removed: the values pass the checks. The joint terms
//! estimated replace `actuator_inertia` (and a `rotor_inertia`, `gear_ratio` pair),
//! `friction_viscous`, `friction_coulomb`, `friction_offset`.

use super::toml_joints::JointEdits;
use dynamics_codegen::Parameter;
use dynamics_identification::identify::about_com::about_com;

/// `text` (a TOML description) with the standard parameters `values` (`parameters`' order)
/// written into its joints.
///
/// # Errors
/// The text is not TOML, its joints are not the robot's, or a value is not finite.
pub fn rewrite(text: &str, parameters: &[Parameter], values: &[f64]) -> Result<String, String> {
    let mut joints = JointEdits::new(text)?;
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
    for l in 0..links {
        let (mass, com, inertia) = about_com(&values[10 * l..10 * l + 10]);
        let joint = l + 1;
        joints.set(l, "mass", number(mass, joint, "mass")?);
        joints.set(l, "com", array(&com, joint, "com")?);
        joints.set(l, "inertia", array(&inertia, joint, "inertia")?);
        joints.remove(l, "check_inertia");
    }
    for (p, &x) in parameters.iter().zip(values) {
        let Parameter::Joint { joint, index } = *p else {
            continue;
        };
        if joint >= links {
            return Err(format!("a joint term of joint {}, of no joint", joint + 1));
        }
        if index == 0 {
            joints.remove(joint, "rotor_inertia");
            joints.remove(joint, "gear_ratio");
        }
        let key = [
            "actuator_inertia",
            "friction_viscous",
            "friction_coulomb",
            "friction_offset",
        ][index];
        joints.set(joint, key, number(x, joint + 1, key)?);
    }
    Ok(joints.finish())
}

/// `x` as a TOML float that reads back as `x` (`1.0`, `0.25`, `1e-19`).
///
/// # Errors
/// `x` is not finite: the estimate of `key` of joint `joint` (1-based) failed.
fn number(x: f64, joint: usize, key: &str) -> Result<String, String> {
    if x == 0.0 {
        // Not `-0.0`, which reads as a sign that matters.
        Ok("0.0".to_string())
    } else if x.is_finite() {
        // `Debug` writes the shortest digits that read back as `x`, with a `.0` or an exponent
        // that keeps it a TOML float.
        Ok(format!("{x:?}"))
    } else {
        Err(format!(
            "the estimate's `{key}` of joint {joint} is {x}, not a number to write"
        ))
    }
}

/// `xs` as a TOML array of floats.
fn array(xs: &[f64], joint: usize, key: &str) -> Result<String, String> {
    let items: Vec<String> = xs
        .iter()
        .map(|&x| number(x, joint, key))
        .collect::<Result<_, _>>()?;
    Ok(format!("[{}]", items.join(", ")))
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

    /// A link and its joint terms written over a description's values, by hand: the link's
    /// mass, centre of mass and inertia about it (exact in binary, so each is written as it
    /// is), the geared drive replaced by its actuator inertia, the unchecked inertia checked,
    /// friction added; the comments stay.
    #[test]
    fn values_are_written_in_place_of_the_descriptions() {
        let text = "\
gravity = [0, 0, -9.81]
[[joints]]
type = \"revolute\"
mass = 1   # kg
com = [0, 0, 0]
inertia = [1, 1, 1, 0, 0, 0]
check_inertia = false
rotor_inertia = 1e-4  # the motor's
gear_ratio = 100
";
        let mut parameters: Vec<Parameter> = (0..10)
            .map(|index| Parameter::Link { link: 0, index })
            .collect();
        parameters.extend((0..2).map(|index| Parameter::Joint { joint: 0, index }));
        let mut values = standard(
            2.0,
            [0.0, 0.0, 0.5],
            [[0.25, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 0.125]],
        )
        .to_vec();
        values.extend([0.0625, 0.5]);
        let expected = "\
gravity = [0, 0, -9.81]
[[joints]]
type = \"revolute\"
mass = 2.0   # kg
com = [0.0, 0.0, 0.5]
inertia = [0.625, 0.375, 0.75, 0.0, 0.0, 0.0]
actuator_inertia = 0.0625
friction_viscous = 0.5
";
        assert_eq!(rewrite(text, &parameters, &values).as_deref(), Ok(expected));
        values[11] = f64::NAN;
        assert_eq!(
            rewrite(text, &parameters, &values),
            Err(
                "the estimate's `friction_viscous` of joint 1 is NaN, not a number to write".into()
            )
        );
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
