//! The schema of a description file, as serde reads it, and its conversion to a
//! [`Robot`]. Absent D-H entries, offsets and spring values are zero.

use super::{frames, FileError, Loaded};
use crate::check::{self, LinkParameter};
use crate::front::angle::{self, unitless_angle};
use crate::front::value::parse_spanned;
use crate::model::{
    snap_angle, Convention, Friction, Joint, JointKind, Link, Placement, Pose, Robot, Spring, Value,
};
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
enum FileConvention {
    Standard,
    Modified,
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
enum FileKind {
    Revolute,
    Prismatic,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileRobot {
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    #[allow(dead_code)]
    description: Option<String>,
    #[serde(default)]
    convention: Option<FileConvention>,
    gravity: [FileValue; 3],
    joints: Vec<FileJoint>,
    /// The tool frame in link frame n, `[x, y, z, roll, pitch, yaw]`.
    #[serde(default)]
    tool: Option<[FileValue; 6]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileJoint {
    #[serde(rename = "type")]
    kind: FileKind,
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
    mass: FileValue,
    #[serde(default)]
    com: Option<[FileValue; 3]>,
    #[serde(default)]
    inertia: Option<[FileValue; 6]>,
    #[serde(default)]
    actuator_inertia: Option<FileValue>,
    #[serde(default)]
    spring_stiffness: Option<FileValue>,
    #[serde(default)]
    spring_rest: Option<FileValue>,
    /// `false` keeps an inertia tensor that fails the physical checks.
    #[serde(default)]
    check_inertia: Option<bool>,
    /// Friction `f_v q̇ + f_c sign(q̇) + f_0` (`tanh(q̇ / ε)` with a smoothing velocity ε): the
    /// keys of the attribute's `friction = (viscous = .., ...)`, prefixed as `spring_*` are.
    #[serde(default)]
    friction_viscous: Option<FileValue>,
    #[serde(default)]
    friction_coulomb: Option<FileValue>,
    #[serde(default)]
    friction_offset: Option<FileValue>,
    #[serde(default)]
    friction_smoothing: Option<FileValue>,
    /// A geared drive: the actuator inertia is `gear_ratio² · rotor_inertia`.
    #[serde(default)]
    rotor_inertia: Option<FileValue>,
    #[serde(default)]
    gear_ratio: Option<FileValue>,
}

impl FileJoint {
    /// Its friction, if it gives any friction key.
    fn friction(&self) -> Option<Friction> {
        let keys = [
            &self.friction_viscous,
            &self.friction_coulomb,
            &self.friction_offset,
        ];
        let given = keys.iter().any(|k| k.is_some()) || self.friction_smoothing.is_some();
        given.then(|| Friction {
            viscous: value(self.friction_viscous.as_ref()),
            coulomb: value(self.friction_coulomb.as_ref()),
            offset: value(self.friction_offset.as_ref()),
            smoothing: self.friction_smoothing.as_ref().map(|v| v.0.clone()),
        })
    }

    /// Its actuator inertia: `actuator_inertia`, or `gear_ratio² · rotor_inertia` (ratio 1
    /// without `gear_ratio`), whose problems go to `deferred` as joint `joint`'s.
    fn actuator_inertia(&self, joint: usize, deferred: &mut Vec<Deferred>) -> Value {
        if self.rotor_inertia.is_none() && self.gear_ratio.is_none() {
            return value(self.actuator_inertia.as_ref());
        }
        if self.actuator_inertia.is_some() {
            deferred.push((joint, "actuator_inertia", "give either `actuator_inertia` or `rotor_inertia` and `gear_ratio` (its N² I_rotor), not both".into()));
        }
        let Some(rotor) = &self.rotor_inertia else {
            deferred.push((joint, "gear_ratio", "`gear_ratio` without `rotor_inertia`: the actuator inertia is gear_ratio² × rotor_inertia".into()));
            return Value::zero();
        };
        let ratio = self
            .gear_ratio
            .as_ref()
            .map_or(Value::Num(Number::ONE), |g| g.0.clone());
        for p in check::gear(&rotor.0, &ratio) {
            let key = if p.parameter == LinkParameter::GearRatio {
                "gear_ratio"
            } else {
                "rotor_inertia"
            };
            deferred.push((joint, key, p.message));
        }
        check::geared_inertia(&rotor.0, &ratio)
    }
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

fn value(v: Option<&FileValue>) -> Value {
    v.map_or_else(Value::zero, |v| v.0.clone())
}

/// The angles (θ, α and the origin's rpy) of joint `joint` written as plain numbers above 2π.
fn angle_problems(joint: usize, j: &FileJoint) -> impl Iterator<Item = Deferred> + '_ {
    let rpy = j.origin.iter().flat_map(|o| o.rpy.iter().flatten());
    [("theta", &j.theta), ("alpha", &j.alpha)]
        .into_iter()
        .filter_map(move |(key, v)| Some((joint, key, v.as_ref()?.1.clone()?)))
        .chain(rpy.filter_map(move |v| Some((joint, "origin", v.1.clone()?))))
}

/// The robot the file describes, with its per-joint check flags (positions are filled in by
/// the format's reader), and the errors that need them.
pub(super) fn convert(
    file: FileRobot,
    default_name: &str,
) -> Result<(Loaded, Vec<Deferred>), FileError> {
    let convention = match file.convention {
        None | Some(FileConvention::Standard) => Convention::Standard,
        Some(FileConvention::Modified) => Convention::Modified,
    };
    if file.joints.is_empty() {
        return Err(super::plain(
            "`joints` is empty: give one entry per joint, base to tip".to_string(),
        ));
    }
    let gravity = file.gravity.map(|g| g.0);
    let frames_given = file.joints.iter().any(FileJoint::has_frame);
    if frames_given && file.convention.is_some() {
        return Err(super::plain(
            "`convention` applies to D-H rows: joints given by `origin` and `axis` are lowered \
             to their own modified D-H table; remove `convention`"
                .to_string(),
        ));
    }
    let tool = file.tool.map(|t| {
        let [x, y, z, roll, pitch, yaw] = t.map(|v| v.0);
        Placement::written([x, y, z], [roll, pitch, yaw])
    });
    let mut joints = Vec::with_capacity(file.joints.len());
    let mut check_inertia = Vec::with_capacity(file.joints.len());
    let mut deferred = Vec::new();
    for (i, j) in file.joints.into_iter().enumerate() {
        deferred.extend(angle_problems(i, &j));
        let kind = match j.kind {
            FileKind::Revolute => JointKind::Revolute,
            FileKind::Prismatic => JointKind::Prismatic,
        };
        let stiffness = value(j.spring_stiffness.as_ref());
        let spring = (!stiffness.is_zero()).then(|| Spring {
            stiffness,
            rest: value(j.spring_rest.as_ref()),
        });
        check_inertia.push(j.check_inertia.unwrap_or(true));
        let actuator_inertia = j.actuator_inertia(i, &mut deferred);
        let friction = j.friction();
        let frame = frames::frame(i, &j, frames_given, &mut deferred);
        let link = Link {
            mass: j.mass.0,
            com: j.com.map_or_else(Default::default, |c| c.map(|v| v.0)),
            inertia: j.inertia.map_or_else(Default::default, |c| c.map(|v| v.0)),
            actuator_inertia,
            spring,
            friction,
        };
        // Angles near quarter turns (1.5708) are those quarter turns, as in frames and URDFs.
        let row = [
            snap_angle(&value(j.theta.as_ref())),
            value(j.d.as_ref()),
            value(j.a.as_ref()),
            snap_angle(&value(j.alpha.as_ref())),
        ];
        joints.push(Joint {
            frame,
            ..Joint::dh(kind, row, link)
        });
    }
    let mut loaded = Loaded {
        robot: Robot {
            name: file.name.unwrap_or_else(|| default_name.to_string()),
            convention,
            gravity,
            joints,
            base: Pose::identity(),
            tool,
        },
        check_inertia,
        positions: Vec::new(),
        gravity: None,
    };
    if frames_given && deferred.is_empty() {
        frames::lower(&mut loaded.robot, &mut deferred);
    }
    Ok((loaded, deferred))
}
