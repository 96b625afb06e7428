//! The schema of a description file, as serde reads it: every value read and checked as it is
//! parsed (a number, or a string in the value grammar), so that its errors carry a line and
//! column. `convert` turns it into a robot.

use crate::front::angle::{self, unitless_angle};
use crate::front::value::parse_spanned;
use crate::model::Value;
use crate::symbolic::Number;
use serde::Deserialize;

/// A value in a description file: a number, or a string holding a value (`"90 deg"`). It is
/// read and checked while the file is parsed, so that its errors carry a line and column.
/// The second field is what is wrong with it as an angle: a plain number above 2π (a number,
/// or a term of a string without a unit).
pub(super) struct FileValue(pub Value, pub Option<String>);

/// An error in joint `.0`'s value of key `.1`, found after parsing: it gets its position
/// from [`Loaded::positions`].
pub(super) type Deferred = (usize, &'static str, String);

/// The message for a number used as an angle, if it is a plain number above 2π.
fn angle_problem(value: Number) -> Option<String> {
    (value.to_f64().abs() > std::f64::consts::TAU).then(|| angle::message(value, true))
}

impl<'de> Deserialize<'de> for FileValue {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ValueVisitor)
    }
}

struct ValueVisitor;

impl serde::de::Visitor<'_> for ValueVisitor {
    type Value = FileValue;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a number, or a string holding a value such as \"90 deg\" or \"m * l^2 / 12\"")
    }

    fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<FileValue, E> {
        if x.is_finite() {
            let value = Value::from_f64(x);
            let angle = value.exact().and_then(angle_problem);
            Ok(FileValue(value, angle))
        } else {
            Err(E::custom(format!("{x} is not a finite number")))
        }
    }

    fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<FileValue, E> {
        let x = Number::int(x);
        Ok(FileValue(Value::Num(x), angle_problem(x)))
    }

    fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<FileValue, E> {
        match i64::try_from(x) {
            Ok(x) => self.visit_i64(x),
            #[allow(clippy::cast_precision_loss)]
            Err(_) => self.visit_f64(x as f64),
        }
    }

    fn visit_str<E: serde::de::Error>(self, text: &str) -> Result<FileValue, E> {
        let spanned = parse_spanned(text).map_err(E::custom)?;
        let v = spanned.value;
        if v.joint_occurrences() > 0 {
            return Err(E::custom(
                "the joint variable `q` has no place in a description file; `theta` (revolute) \
                 or `d` (prismatic) is the offset added to it",
            ));
        }
        // Here, so that the error has the string's line and column.
        if v.divides_by_zero() {
            return Err(E::custom(format!("division by zero in `{text}`")));
        }
        if v.exact().is_some_and(|n| !n.to_f64().is_finite()) {
            return Err(E::custom(format!("`{text}` is not a finite number")));
        }
        let angle = unitless_angle(&spanned.unitless, true).map(|(_, message)| message);
        Ok(FileValue(v, angle))
    }
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum FileConvention {
    Standard,
    Modified,
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum FileKind {
    Revolute,
    Prismatic,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileRobot {
    #[serde(default)]
    pub(super) name: Option<String>,
    #[serde(default)]
    #[allow(dead_code)]
    pub(super) description: Option<String>,
    #[serde(default)]
    pub(super) convention: Option<FileConvention>,
    pub(super) gravity: [FileValue; 3],
    pub(super) joints: Vec<FileJoint>,
    /// The tool frame in link frame n, `[x, y, z, roll, pitch, yaw]`.
    #[serde(default)]
    pub(super) tool: Option<[FileValue; 6]>,
    /// The pruned models' tolerance and envelope, as the attribute's `simplify(...)`.
    #[serde(default)]
    pub(super) simplify: Option<super::simplify::FileSimplify>,
    /// The body of a robot on a free-flying base (`base = floating` in the derive).
    #[serde(default)]
    pub(super) floating: Option<FileFloating>,
}

/// `[floating]`: the floating body's mass, centre of mass and inertia about it, in the base
/// frame (frame 0), as a joint's link.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileFloating {
    pub(super) mass: FileValue,
    #[serde(default)]
    pub(super) com: Option<[FileValue; 3]>,
    #[serde(default)]
    pub(super) inertia: Option<[FileValue; 6]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileJoint {
    #[serde(rename = "type")]
    pub(super) kind: FileKind,
    /// A name other joints' `parent` can give.
    #[serde(default)]
    pub(super) name: Option<String>,
    /// The antecedent, in a tree: an earlier joint's 1-based number (0: the base) or name;
    /// default: the joint before.
    #[serde(default)]
    pub(super) parent: Option<FileParent>,
    /// The joint it follows, if a mimic joint: `mimic = { joint = 2, multiplier = -1,
    /// offset = 0.1 }`.
    #[serde(default)]
    pub(super) mimic: Option<FileMimic>,
    /// Khalil-Kleinfinger's γ and b (modified D-H rows only): the turn about and offset along
    /// the antecedent's z onto the common normal to this joint's axis.
    #[serde(default)]
    pub(super) gamma: Option<FileValue>,
    #[serde(default)]
    pub(super) b: Option<FileValue>,
    #[serde(default)]
    pub(super) theta: Option<FileValue>,
    #[serde(default)]
    pub(super) d: Option<FileValue>,
    #[serde(default)]
    pub(super) a: Option<FileValue>,
    #[serde(default)]
    pub(super) alpha: Option<FileValue>,
    /// The joint frame's placement, URDF style, instead of `theta`, `d`, `a`, `alpha`.
    #[serde(default)]
    pub(super) origin: Option<FileOrigin>,
    /// The unit axis in the joint frame (default `[0, 0, 1]`), with `origin`.
    #[serde(default)]
    pub(super) axis: Option<[FileValue; 3]>,
    pub(super) mass: FileValue,
    #[serde(default)]
    pub(super) com: Option<[FileValue; 3]>,
    #[serde(default)]
    pub(super) inertia: Option<[FileValue; 6]>,
    #[serde(default)]
    pub(super) actuator_inertia: Option<FileValue>,
    #[serde(default)]
    pub(super) spring_stiffness: Option<FileValue>,
    #[serde(default)]
    pub(super) spring_rest: Option<FileValue>,
    /// `false` keeps an inertia tensor that fails the physical checks.
    #[serde(default)]
    pub(super) check_inertia: Option<bool>,
    /// Friction `f_v q̇ + f_c sign(q̇) + f_0` (`tanh(q̇ / ε)` with a smoothing velocity ε): the
    /// keys of the attribute's `friction = (viscous = .., ...)`, prefixed as `spring_*` are.
    #[serde(default)]
    pub(super) friction_viscous: Option<FileValue>,
    #[serde(default)]
    pub(super) friction_coulomb: Option<FileValue>,
    #[serde(default)]
    pub(super) friction_offset: Option<FileValue>,
    #[serde(default)]
    pub(super) friction_smoothing: Option<FileValue>,
    /// A geared drive: the actuator inertia is `gear_ratio² · rotor_inertia`.
    #[serde(default)]
    pub(super) rotor_inertia: Option<FileValue>,
    #[serde(default)]
    pub(super) gear_ratio: Option<FileValue>,
}

/// `mimic = { joint = 2 | "name", multiplier = k, offset = o }`: `q = k q_joint + o`
/// (multiplier 1 and offset 0 by default).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileMimic {
    pub(super) joint: FileParent,
    #[serde(default)]
    pub(super) multiplier: Option<FileValue>,
    #[serde(default)]
    pub(super) offset: Option<FileValue>,
}

/// `origin = { xyz = [..], rpy = [..] }`: translation, and roll, pitch, yaw in radians.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileOrigin {
    #[serde(default)]
    pub(super) xyz: Option<[FileValue; 3]>,
    #[serde(default)]
    pub(super) rpy: Option<[FileValue; 3]>,
}

/// A joint's `parent`: a number or a name, as written.
pub(super) enum FileParent {
    Number(u64),
    Name(String),
}

impl<'de> serde::Deserialize<'de> for FileParent {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ParentVisitor)
    }
}

struct ParentVisitor;

impl serde::de::Visitor<'_> for ParentVisitor {
    type Value = FileParent;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("an earlier joint's number (1 for the first, 0 for the base) or name")
    }

    fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<FileParent, E> {
        Ok(FileParent::Number(x))
    }

    fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<FileParent, E> {
        u64::try_from(x).map(FileParent::Number).map_err(|_| {
            E::custom(format!(
                "parent {x}: name an earlier joint by its number (1 for the first) or name, or \
                 the base by 0"
            ))
        })
    }

    fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<FileParent, E> {
        Ok(FileParent::Name(name.to_string()))
    }
}
