//! The model of the standard parameters: per link j, `π_j = [M, MX, MY, MZ, XX, XY, YY, XZ,
//! YZ, ZZ]_j` (Khalil's names for `m, m c, I` about the link frame's origin, in the
//! regressor's order) and the joint terms asked for: per joint, the actuator inertia `IA` and the
//! friction coefficients `FV` (viscous), `FC` (Coulomb), `FO` (offset), whose columns are
//! `q̈_i, q̇_i, sign(q̇_i), 1` in joint i's equation.
//!
//! Not every standard parameter is identifiable: the rank check names those that the others'
//! columns already span.

use super::model::Entries;
use dynamics_codegen::Equations;

/// The joint terms to identify beside the rigid bodies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JointTerms {
    pub rotors: bool,
    pub viscous: bool,
    pub coulomb: bool,
    pub offset: bool,
}

impl JointTerms {
    /// Which of the joint columns `[q̈, q̇, sign(q̇), 1]` are asked for, with their names.
    fn chosen(self) -> impl Iterator<Item = (usize, &'static str)> {
        let wanted = [self.rotors, self.viscous, self.coulomb, self.offset];
        ["IA", "FV", "FC", "FO"]
            .into_iter()
            .enumerate()
            .filter(move |&(k, _)| wanted[k])
    }

    /// The terms in words, for the report.
    #[must_use]
    pub fn describe(self) -> String {
        let words = ["actuator inertia", "viscous", "Coulomb", "offset"];
        let chosen: Vec<&str> = self.chosen().map(|(k, _)| words[k]).collect();
        if chosen.is_empty() {
            "none".into()
        } else {
            chosen.join(", ")
        }
    }
}

/// The link parameters' names, in the regressor's order.
const LINK: [&str; 10] = ["M", "MX", "MY", "MZ", "XX", "XY", "YY", "XZ", "YZ", "ZZ"];

/// The entries of the standard parameters' model of `eq` (traced with its regressor), the
/// links' parameters first, then each joint's terms.
///
/// # Errors
/// Equations traced without the regressor.
pub fn entries<'a>(
    eq: &'a Equations,
    terms: JointTerms,
    fields: &'a [f64],
) -> Result<Entries<'a>, String> {
    let regressor = eq
        .regressor
        .as_ref()
        .ok_or("the equations were traced without the regressor")?;
    let n = eq.dof;
    let mut names = Vec::new();
    let mut described = Vec::new();
    for (j, parameters) in regressor.parameters.iter().enumerate() {
        names.extend(LINK.iter().map(|p| format!("{p}{}", j + 1)));
        described.extend(parameters);
    }
    let chosen: Vec<(usize, &str)> = terms.chosen().collect();
    for j in 0..n {
        for &(k, name) in &chosen {
            names.push(format!("{name}{}", j + 1));
            described.push(regressor.joint_parameters[j][k]);
        }
    }
    let rows = (0..n)
        .map(|i| {
            let links = regressor.columns[i].iter().flatten().copied().map(Some);
            // A joint's terms are in its own equation only.
            let joints = (0..n).flat_map(|j| {
                let columns = &regressor.joint_columns[j];
                chosen
                    .iter()
                    .map(move |&(k, _)| (i == j).then(|| columns[k]))
            });
            links.chain(joints).collect()
        })
        .collect();
    Ok(Entries {
        graph: &eq.graph,
        names,
        rows,
        described,
        angle_offsets: &eq.angle_offsets,
        fields,
    })
}
