//! A description file's `[simplify]` table (`"simplify": {..}` in JSON): the keys of the
//! attribute's `simplify(...)`, each one number or a list of one per joint, with their lines
//! and columns for the errors of [`crate::front::simplify`].

use crate::front::simplify::given::Given;
use crate::front::sources::{At, Sources};
use serde::Deserialize;

/// The table as serde reads it; an unknown key is an error at its position.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileSimplify {
    #[serde(default)]
    tolerance: Option<Numbers>,
    #[serde(default)]
    rated: Option<Numbers>,
    #[serde(default)]
    tolerance_percent: Option<Numbers>,
    #[serde(default)]
    q_min: Option<Numbers>,
    #[serde(default)]
    q_max: Option<Numbers>,
    #[serde(default)]
    qd_max: Option<Numbers>,
    #[serde(default)]
    qdd_max: Option<Numbers>,
}

/// One number for every joint, or one per joint.
#[derive(Deserialize)]
#[serde(untagged, expecting = "a number, or a list of numbers (one per joint)")]
enum Numbers {
    One(f64),
    Many(Vec<f64>),
}

impl FileSimplify {
    /// The keys given, placed at the table's position until [`place`] finds their own.
    pub(super) fn given(self) -> Given<At> {
        let keys = [
            ("tolerance", self.tolerance),
            ("rated", self.rated),
            ("tolerance_percent", self.tolerance_percent),
            ("q_min", self.q_min),
            ("q_max", self.q_max),
            ("qd_max", self.qd_max),
            ("qdd_max", self.qdd_max),
        ];
        let keys = keys.into_iter().filter_map(|(key, numbers)| {
            let values = match numbers? {
                Numbers::One(x) => vec![x],
                Numbers::Many(v) => v,
            };
            Some((key, values, (0, 0)))
        });
        Given {
            at: (0, 0),
            keys: keys.collect(),
        }
    }
}

/// Each key of `given` at its line and column in the file, as `sources` found them (the
/// table's own under the key `simplify`).
pub(super) fn place(given: &mut Given<At>, sources: &Sources<At>) {
    if let Some(&at) = sources.simplify.get("simplify") {
        given.at = at;
    }
    for (key, _, at) in &mut given.keys {
        *at = sources.simplify.get(*key).copied().unwrap_or(given.at);
    }
}
