//! A description file's schema converted to a [`Robot`], with the errors found after parsing
//! kept with the key they concern, so that they get its line and column. Absent D-H entries,
//! offsets and spring values are zero.

use super::schema::{Deferred, FileConvention, FileJoint, FileKind, FileRobot, FileValue};
use super::{frames, tree};
use crate::check;
use crate::front::errors::FileError;
use crate::front::sources::{Loaded, Positions};
use crate::model::{
    snap_angle, Convention, FreeFlyer, Friction, Joint, JointKind, Link, Placement, Pose, Robot,
    Spring, Value,
};
use crate::symbolic::Number;

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
            deferred.push((joint, p.parameter.key(), p.message));
        }
        check::geared_inertia(&rotor.0, &ratio)
    }
}

fn value(v: Option<&FileValue>) -> Value {
    v.map_or_else(Value::zero, |v| v.0.clone())
}

/// The angles (θ, α, γ and the origin's rpy) of joint `joint` written as plain numbers above 2π.
fn angle_problems(joint: usize, j: &FileJoint) -> impl Iterator<Item = Deferred> + '_ {
    let rpy = j.origin.iter().flat_map(|o| o.rpy.iter().flatten());
    [
        ("theta", &j.theta),
        ("alpha", &j.alpha),
        ("gamma", &j.gamma),
    ]
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
        return Err(plain(
            "`joints` is empty: give one entry per joint, base to tip".to_string(),
        ));
    }
    let gravity = file.gravity.map(|g| g.0);
    let frames_given = file.joints.iter().any(FileJoint::has_frame);
    if frames_given && file.convention.is_some() {
        return Err(plain(
            "`convention` applies to D-H rows: joints given by `origin` and `axis` are lowered \
             to their own modified D-H table; remove `convention`"
                .to_string(),
        ));
    }
    let mut joints = Vec::with_capacity(file.joints.len());
    let mut check_inertia = Vec::with_capacity(file.joints.len());
    let mut deferred = Vec::new();
    let branches = tree::branches(&file.joints, convention, frames_given, &mut deferred);
    let per_joint = branches
        .into_iter()
        .zip(tree::mimics(&file.joints, &mut deferred));
    for ((i, j), (branch, mimic)) in file.joints.into_iter().enumerate().zip(per_joint) {
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
            branch,
            mimic,
            ..Joint::dh(kind, row, link)
        });
    }
    let mut loaded = Loaded {
        // Before `gravity` moves into the robot.
        floating: file.floating.map(|body| free_flyer(body, &gravity)),
        robot: Robot {
            name: file.name.unwrap_or_else(|| default_name.to_string()),
            convention,
            gravity,
            joints,
            base: Pose::identity(),
            tool: file.tool.map(tool_placement),
            tips: Vec::new(),
        },
        check_inertia,
        sources: Positions::default(),
        simplify: file.simplify.map(super::simplify::FileSimplify::given),
    };
    if frames_given && deferred.is_empty() {
        frames::lower(&mut loaded.robot, &mut deferred);
    }
    Ok((loaded, deferred))
}

/// The file's `[floating]` body, with its gravity as written (in the world frame: the robot's
/// own is turned into its frame 0 when joints given by frames are lowered).
fn free_flyer(body: super::schema::FileFloating, gravity: &[Value; 3]) -> FreeFlyer {
    FreeFlyer {
        link: "base".to_string(),
        body: Link {
            mass: body.mass.0,
            com: body.com.map_or_else(Default::default, |c| c.map(|v| v.0)),
            inertia: body
                .inertia
                .map_or_else(Default::default, |c| c.map(|v| v.0)),
            ..Link::default()
        },
        gravity: gravity.clone(),
    }
}

/// The file's `tool = [x, y, z, roll, pitch, yaw]`.
fn tool_placement(tool: [FileValue; 6]) -> Placement {
    let [x, y, z, roll, pitch, yaw] = tool.map(|v| v.0);
    Placement::written([x, y, z], [roll, pitch, yaw])
}

/// The loaded robot, or the first of the errors found after parsing, at its position (that of
/// the joint's `type` where the file does not write the key).
pub(super) fn first_error(mut loaded: Loaded, deferred: &[Deferred]) -> Result<Loaded, FileError> {
    if let Some(given) = &mut loaded.simplify {
        super::simplify::place(given, &loaded.sources);
    }
    let Some((joint, key, message)) = deferred.first() else {
        return Ok(loaded);
    };
    let (line, column) = loaded
        .sources
        .get(*joint, key)
        .or_else(|| loaded.sources.get(*joint, "type"))
        .map_or((None, None), |(l, c)| (Some(*l), Some(*c)));
    Err(FileError {
        message: format!("joint {}: {message}", joint + 1),
        line,
        column,
        about: None,
    })
}

pub(super) fn plain(message: String) -> FileError {
    FileError {
        message,
        line: None,
        column: None,
        about: None,
    }
}
