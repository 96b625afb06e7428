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

#[cfg(test)]
mod tests {
    use crate::front::file::load;
    use crate::front::simplify::given::Defaults;
    use crate::model::JointEnvelope;

    const ROBOT: &str = "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
                         [[joints]]\ntype = \"prismatic\"\nmass = 1\n";

    /// TOML and JSON give the same request, each key placed at its value.
    #[test]
    fn the_table_with_its_positions() {
        let toml = format!("{ROBOT}\n[simplify]\ntolerance = [0.5, 2]\nqd_max = 3\n");
        let loaded = load("a.toml", &toml).expect("toml");
        let given = loaded.simplify.expect("simplify");
        assert_eq!(given.at, (9, 1));
        assert_eq!(given.keys[0], ("tolerance", vec![0.5, 2.0], (10, 13)));
        assert_eq!(given.keys[1], ("qd_max", vec![3.0], (11, 10)));
        let json = "{\"gravity\": [0, 0, -9.81], \"joints\": [{\"type\": \"revolute\", \"mass\": 1}],\n \"simplify\": {\"tolerance\": 0.5,\n  \"q_min\": [-1]}}";
        let given = load("a.json", json)
            .expect("json")
            .simplify
            .expect("simplify");
        assert_eq!(given.at, (2, 14));
        assert_eq!(given.keys[0], ("tolerance", vec![0.5], (2, 28)));
        assert_eq!(given.keys[1], ("q_min", vec![-1.0], (3, 12)));
        let defaults = [JointEnvelope {
            lower: -1.0,
            upper: 1.0,
            speed: 2.0,
            acceleration: 5.0,
        }];
        let request = given
            .resolve(&Defaults {
                joints: defaults.to_vec(),
                rated: None,
                coordinates: false,
            })
            .expect("resolves");
        assert_eq!(request.tolerance, [0.5]);
        assert_eq!(request.envelope.joints[0].lower, -1.0);
    }

    /// An unknown key is an error at its line; a list of the wrong length at its key's.
    #[test]
    fn mistakes_at_their_positions() {
        let toml = format!("{ROBOT}\n[simplify]\ntolerance = 1\nq_mni = 3\n");
        let e = load("a.toml", &toml).err().expect("an error");
        assert_eq!(e.line, Some(11), "{e}");
        assert!(e.message.contains("unknown field `q_mni`"), "{e}");
        let toml = format!("{ROBOT}\n[simplify]\ntolerance = 1\nqd_max = [1, 2, 3]\n");
        let given = load("a.toml", &toml)
            .expect("toml")
            .simplify
            .expect("simplify");
        let defaults = [JointEnvelope {
            lower: -1.0,
            upper: 1.0,
            speed: 2.0,
            acceleration: 5.0,
        }; 2];
        let Err(problems) = given.resolve(&Defaults {
            joints: defaults.to_vec(),
            rated: None,
            coordinates: false,
        }) else {
            panic!("a list of three for two joints resolved")
        };
        assert_eq!(problems.len(), 1);
        assert_eq!(problems[0].0, (11, 10));
        assert!(
            problems[0].1.contains(
                "`qd_max` takes one number for every joint or one per joint (2), found 3"
            ),
            "{problems:?}"
        );
    }
}
