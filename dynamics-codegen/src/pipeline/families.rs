//! The door's families by name: the opt-in families of methods a driver asks for by their
//! names in the method table (`derivatives`, `regressor`, ...), as the attribute's
//! `FAMILY = true` does.

use super::Diagnostic;
use crate::method::{Family, FamilySet};

/// Every family that is not opt-in, and the opt-in ones `names` name.
///
/// # Errors
/// The first name that is not an opt-in family's, as [`opt_in_family`] refuses it.
pub fn families<S: AsRef<str>>(names: &[S]) -> Result<FamilySet, Diagnostic> {
    names.iter().try_fold(FamilySet::default(), |set, name| {
        opt_in_family(name.as_ref()).map(|family| set.with(family))
    })
}

/// The opt-in family `name`; not the simplified models', which need an envelope and
/// tolerances (a description file's `[simplify]`).
///
/// # Errors
/// A name of no opt-in family (the help lists them), or the simplified models'.
pub fn opt_in_family(name: &str) -> Result<Family, Diagnostic> {
    match Family::from_name(name).filter(|f| f.is_opt_in()) {
        Some(Family::Simplified) => Err(Diagnostic::of_caller(format!(
            "`{name}` needs an envelope and tolerances"
        ))
        .with_help("the simplified models come from a `[simplify]` table in the description file")),
        Some(family) => Ok(family),
        None => Err(
            Diagnostic::of_caller(format!("`{name}` is not an opt-in family of methods"))
                .with_help(format!(
                    "the opt-in families: {}",
                    asked_by_name().join(", ")
                )),
        ),
    }
}

/// The opt-in families a driver asks for by name: all but the simplified models.
#[must_use]
pub fn asked_by_name() -> Vec<&'static str> {
    let simplified = Family::Simplified.name();
    Family::opt_in_names()
        .into_iter()
        .filter(|&n| n != simplified)
        .collect()
}
