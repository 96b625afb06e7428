//! `identify --consistent --description-out FILE.toml`: the robot's TOML description with the
//! consistent estimate's values in place of its own, everything else (comments, layout, keys)
//! kept, so that `dynamics` and `#[dynamics(file = ..)]` read it back.
//!
//! A link's standard parameters `[m, h, I_o]` (about the link frame's origin) become the
//! description's mass `m`, centre of mass `c = h / m` and inertia about the centre of mass by
//! the parallel-axis theorem, `I_c = I_o − m (|c|² 1 − c cᵀ)` (`Ixx_c = Ixx − m (cy² + cz²)`,
//! `Ixy_c = Ixy + m cx cy`, entries `−∫xy dm`), written `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`; a
//! massless link (J ⪰ 0 then forces `h = 0`) keeps `c = 0` and `I_c = I_o`. Its
//! `check_inertia = false`, if any, is removed: the values pass the checks. The joint terms
//! estimated replace `actuator_inertia` (and a `rotor_inertia`, `gear_ratio` pair),
//! `friction_viscous`, `friction_coulomb`, `friction_offset`.

use dynamics_codegen::trace::base_parameters::Parameter;
use toml_edit::{value, Array, DocumentMut};

/// Mass, centre of mass and inertia about it of a link's ten standard parameters.
#[must_use]
pub fn about_com(pi: &[f64]) -> (f64, [f64; 3], [f64; 6]) {
    let [m, hx, hy, hz, xx, xy, yy, xz, yz, zz] = [
        pi[0], pi[1], pi[2], pi[3], pi[4], pi[5], pi[6], pi[7], pi[8], pi[9],
    ];
    if m <= 0.0 {
        return (0.0, [0.0; 3], [xx, yy, zz, xy, xz, yz]);
    }
    let [cx, cy, cz] = [hx / m, hy / m, hz / m];
    let inertia = [
        xx - m * (cy * cy + cz * cz),
        yy - m * (cx * cx + cz * cz),
        zz - m * (cx * cx + cy * cy),
        xy + m * cx * cy,
        xz + m * cx * cz,
        yz + m * cy * cz,
    ];
    (m, [cx, cy, cz], inertia)
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
}
