//! The request as read, the same for the attribute and description files: the keys (each a
//! list of numbers with where it was written) resolved into one tolerance and one envelope
//! per joint, defaults filled in, every mistake placed on the key that made it. It imports
//! nothing else of the front end, which files its places with it (`sources`).

use crate::model::{Envelope, JointEnvelope, JointKind, Simplification};
use std::f64::consts::PI;

/// The keys of `simplify(...)`, in the order errors list them.
pub const KEYS: &[&str] = &[
    "tolerance",
    "rated",
    "tolerance_percent",
    "q_min",
    "q_max",
    "qd_max",
    "qdd_max",
];

/// The default largest speed (rad/s or m/s) and acceleration (rad/s² or m/s²), as
/// `dynamics inspect --simplified` takes them.
pub const DEFAULT_SPEED: f64 = 2.0;
/// See [`DEFAULT_SPEED`].
pub const DEFAULT_ACCELERATION: f64 = 5.0;

/// What `simplify(...)` gives: each key with its numbers and their place `P` (tokens, or a
/// file's line and column), and the place of the whole request.
pub struct Given<P> {
    /// Where `simplify` is written.
    pub at: P,
    /// Each key given, one of [`KEYS`], with its values.
    pub keys: Vec<(&'static str, Vec<f64>, P)>,
}

/// What a request takes where it does not say: each joint's envelope, and the rated torques
/// of `tolerance_percent` (a URDF's `<limit effort>`, where every joint has one).
pub struct Defaults {
    /// Per joint, base to tip.
    pub joints: Vec<JointEnvelope>,
    /// Per joint, or `None`: then `tolerance_percent` needs `rated`.
    pub rated: Option<Vec<f64>>,
    /// Whether the robot has mimic joints: then the lists are per coordinate, and the
    /// messages say so.
    pub coordinates: bool,
}

/// The default envelope of a joint of `kind`: ±π rad or ±1 m, `DEFAULT_SPEED`,
/// `DEFAULT_ACCELERATION`.
#[must_use]
pub fn default_joint(kind: JointKind) -> JointEnvelope {
    let range = match kind {
        JointKind::Revolute => PI,
        JointKind::Prismatic => 1.0,
    };
    JointEnvelope {
        lower: -range,
        upper: range,
        speed: DEFAULT_SPEED,
        acceleration: DEFAULT_ACCELERATION,
    }
}

impl<P: Copy> Given<P> {
    /// The values of `key`, one per joint (one value given is every joint's), checked
    /// with `valid` (which says what is wrong); `None` where not given.
    fn per_joint(
        &self,
        key: &str,
        (n, each): (usize, &str),
        valid: fn(f64) -> Option<&'static str>,
        errors: &mut Vec<(P, String)>,
    ) -> Option<Vec<f64>> {
        let (_, values, at) = self.keys.iter().find(|(k, _, _)| *k == key)?;
        if values.len() != 1 && values.len() != n {
            let count = values.len();
            let takes = if n == 1 {
                "one number".to_string()
            } else {
                format!("one number for every {each} or one per {each} ({n})")
            };
            errors.push((*at, format!("`{key}` takes {takes}, found {count}")));
            return None;
        }
        if let Some((v, problem)) = values.iter().find_map(|&v| Some((v, valid(v)?))) {
            errors.push((*at, format!("`{key}` takes {problem}, found {v}")));
            return None;
        }
        Some(if values.len() == 1 {
            vec![values[0]; n]
        } else {
            values.clone()
        })
    }

    /// The request for a robot whose joints take `defaults` where it does not say.
    ///
    /// # Errors
    /// Each mistake with its place: a list of the wrong length, a negative or non-finite
    /// value, a range that is empty, no tolerance or two.
    pub fn resolve(&self, defaults: &Defaults) -> Result<Simplification, Vec<(P, String)>> {
        let rated = defaults.rated.as_deref();
        // A mimic joint follows its joint: the lists are per coordinate.
        let each = if defaults.coordinates {
            "coordinate"
        } else {
            "joint"
        };
        let defaults = &defaults.joints;
        let n = (defaults.len(), each);
        let mut errors = Vec::new();
        let tolerance = self.tolerance(n, rated, &mut errors);
        let finite = |v: f64| (!v.is_finite()).then_some("finite numbers");
        let lower = self.per_joint("q_min", n, finite, &mut errors);
        let upper = self.per_joint("q_max", n, finite, &mut errors);
        let speed = self.per_joint("qd_max", n, non_negative, &mut errors);
        let acceleration = self.per_joint("qdd_max", n, non_negative, &mut errors);
        let joints: Vec<JointEnvelope> = (0..n.0)
            .map(|i| JointEnvelope {
                lower: lower.as_ref().map_or(defaults[i].lower, |v| v[i]),
                upper: upper.as_ref().map_or(defaults[i].upper, |v| v[i]),
                speed: speed.as_ref().map_or(defaults[i].speed, |v| v[i]),
                acceleration: acceleration
                    .as_ref()
                    .map_or(defaults[i].acceleration, |v| v[i]),
            })
            .collect();
        if let Some(i) = joints.iter().position(|j| j.lower > j.upper) {
            let at = self.place("q_min").unwrap_or(self.at);
            let j = &joints[i];
            let message = format!(
                "{each} {}: `q_min` ({}) is above `q_max` ({})",
                i + 1,
                j.lower,
                j.upper
            );
            errors.push((at, message));
        }
        match tolerance {
            Some(tolerance) if errors.is_empty() => Ok(Simplification {
                tolerance,
                envelope: Envelope { joints },
            }),
            _ => Err(errors),
        }
    }

    fn place(&self, key: &str) -> Option<P> {
        self.keys
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|&(_, _, at)| at)
    }

    /// `tolerance`, or `rated` torques with `tolerance_percent`: one of the two. `rated` may
    /// be left to `default_rated` (a URDF's efforts).
    fn tolerance(
        &self,
        n: (usize, &str),
        default_rated: Option<&[f64]>,
        errors: &mut Vec<(P, String)>,
    ) -> Option<Vec<f64>> {
        let absolute = self.per_joint("tolerance", n, non_negative, errors);
        let rated = self.per_joint("rated", n, non_negative, errors);
        let percent = self.per_joint("tolerance_percent", (1, n.1), non_negative, errors);
        let given = |key| self.place(key).is_some();
        let relative = given("rated") || given("tolerance_percent");
        if given("tolerance") && relative {
            let at = self.place("rated").or(self.place("tolerance_percent"));
            errors.push((at.unwrap_or(self.at), "give either `tolerance` (N·m or N per joint) or `rated` with `tolerance_percent`, not both".into()));
            return None;
        }
        if relative {
            let rated = match (rated, default_rated) {
                (Some(rated), _) => Some(rated),
                (None, Some(efforts)) if !given("rated") => Some(efforts.to_vec()),
                (None, _) => None,
            };
            let no_rated = !given("rated") && default_rated.is_none();
            if !given("tolerance_percent") || no_rated {
                let efforts = if no_rated {
                    " (a URDF's `<limit effort>` on every joint gives `rated`)"
                } else {
                    ""
                };
                let message = format!("`rated` (each joint's rated torque) and `tolerance_percent` go together: the tolerance is that percentage of each rated torque{efforts}");
                errors.push((self.at, message));
                return None;
            }
            let (rated, percent) = (rated?, percent?);
            return Some(rated.iter().map(|r| r * percent[0] / 100.0).collect());
        }
        if !given("tolerance") {
            let message = "`simplify` needs a tolerance: `tolerance = 0.5` (N·m or N, one for every joint or one per joint), or `rated = [..]` with `tolerance_percent = 1`";
            errors.push((self.at, message.into()));
        }
        absolute
    }
}

/// `None` for a finite number ≥ 0, else what it must be.
fn non_negative(v: f64) -> Option<&'static str> {
    (!(v.is_finite() && v >= 0.0)).then_some("finite numbers ≥ 0")
}
