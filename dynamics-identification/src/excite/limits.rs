//! Each joint's limits for the exciting motion, and where each came from: the command line
//! (one value for every joint, or one per joint), else a URDF's `<limit lower upper velocity>`
//! (a range where both ends are written; URDF has no acceleration limit), else a default.
//!
//! The defaults are deliberately modest, for a robot whose limits nobody gave: a revolute joint
//! within ±π/2 rad of its zero, at most 1 rad/s and 5 rad/s²; a prismatic joint within ±0.1 m,
//! 0.2 m/s and 1 m/s². A real robot's own limits should be given.

use super::fourier::Limits;
use crate::Error;
use dynamics_codegen::model::{JointKind, Robot};
use dynamics_codegen::pipeline::Limit;

/// Where a limit came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    Option,
    Urdf,
    Default,
}

impl Origin {
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            Origin::Option => "option",
            Origin::Urdf => "URDF",
            Origin::Default => "default",
        }
    }
}

/// A joint's limits, with where each came from: lower, upper, speed, acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointLimits {
    pub limits: Limits,
    pub origins: [Origin; 4],
}

/// The limits asked for on the command line (lower, upper, speed, acceleration): each `None`,
/// one value for every joint, or one per joint.
pub type Asked<'a> = [Option<&'a [f64]>; 4];

/// The options' names, in [`Asked`]'s order.
pub const OPTIONS: [&str; 4] = ["--q-min", "--q-max", "--qd-max", "--qdd-max"];

/// Per coordinate of `robot` (every joint but the mimic ones, which follow theirs), its
/// limits: asked for, else from `urdf` (per joint, if the robot is one), else the defaults;
/// narrowed to keep each mimic joint following it (`q_m = k q_j + o`) within its own URDF
/// `<limit>`s, mapped through its rule (`(lower_m − o) / k`, `velocity_m / |k|`).
///
/// # Errors
/// A list whose length is neither 1 nor the coordinates', an empty range, a speed or
/// acceleration limit that is not positive ([`Error::Setting`]): the option's name and the
/// joint.
pub fn joint_limits(
    robot: &Robot,
    urdf: Option<&[Limit]>,
    asked: Asked,
) -> Result<Vec<JointLimits>, Error> {
    let coordinates = robot.coordinates();
    let n = coordinates.len();
    let each = if robot.has_mimics() {
        "coordinate"
    } else {
        "joint"
    };
    if let Some((k, list)) = (0..4).find_map(|k| {
        asked[k]
            .filter(|v| v.len() != 1 && v.len() != n)
            .map(|v| (k, v))
    }) {
        return Err(Error::Setting(format!(
            "{}: {} values; give one for every {each} or one for each of the {n} {each}s",
            OPTIONS[k],
            list.len()
        )));
    }
    let mut out = Vec::with_capacity(n);
    for (c, &j) in coordinates.iter().enumerate() {
        let file = file_limits(urdf, j);
        let defaults = defaults(robot.joints[j].kind);
        let mut values = [0.0; 4];
        let mut origins = [Origin::Default; 4];
        for k in 0..4 {
            let given = asked[k].map(|v| if v.len() == 1 { v[0] } else { v[c] });
            (values[k], origins[k]) = match (given, file[k]) {
                (Some(x), _) => (x, Origin::Option),
                (None, Some(x)) => (x, Origin::Urdf),
                (None, None) => (defaults[k], Origin::Default),
            };
        }
        for mimic in followers(robot, urdf, j) {
            for (k, x) in mimic.into_iter().enumerate() {
                let Some(x) = x else { continue };
                let tighter = if k == 0 { x > values[k] } else { x < values[k] };
                if tighter {
                    (values[k], origins[k]) = (x, Origin::Urdf);
                }
            }
        }
        let [lower, upper, velocity, acceleration] = values;
        let joint = j + 1;
        if lower >= upper {
            return Err(Error::Setting(format!(
                "joint {joint}: the range [{lower}, {upper}] is empty (--q-min, --q-max, and \
                 the URDF's limits of the mimic joints that follow it)"
            )));
        }
        for (k, x) in [(2, velocity), (3, acceleration)] {
            if x <= 0.0 {
                return Err(Error::Setting(format!(
                    "{}: joint {joint}: {x} is not positive",
                    OPTIONS[k]
                )));
            }
        }
        out.push(JointLimits {
            limits: Limits {
                lower,
                upper,
                velocity,
                acceleration,
            },
            origins,
        });
    }
    Ok(out)
}

/// Joint `j`'s limits in `urdf` (lower, upper, speed; URDF has no acceleration limit): a range
/// only where both ends are written (URDF's default for a missing end is 0).
fn file_limits(urdf: Option<&[Limit]>, j: usize) -> [Option<f64>; 4] {
    let file = urdf.and_then(|u| u.get(j)).copied().unwrap_or_default();
    let range = match (file.lower, file.upper) {
        (Some(l), Some(u)) if l < u => [Some(l), Some(u)],
        _ => [None, None],
    };
    [range[0], range[1], file.velocity.filter(|v| *v > 0.0), None]
}

/// The URDF limits of each mimic joint that follows joint `j`, in j's terms.
fn followers(robot: &Robot, urdf: Option<&[Limit]>, j: usize) -> Vec<[Option<f64>; 4]> {
    let number = |v: &dynamics_codegen::model::Value| v.eval(&|_| None);
    let mut out = Vec::new();
    for (m, joint) in robot.joints.iter().enumerate() {
        let Some(rule) = joint.mimic.as_ref().filter(|r| r.joint == j) else {
            continue;
        };
        let (Some(k), Some(o)) = (number(&rule.multiplier), number(&rule.offset)) else {
            continue;
        };
        if k == 0.0 {
            continue;
        }
        let [lower, upper, velocity, _] = file_limits(urdf, m);
        let range = lower.zip(upper).map(|(l, u)| {
            let (a, b) = ((l - o) / k, (u - o) / k);
            (a.min(b), a.max(b))
        });
        out.push([
            range.map(|r| r.0),
            range.map(|r| r.1),
            velocity.map(|v| v / k.abs()),
            None,
        ]);
    }
    out
}

/// The defaults of a joint of this kind: lower, upper, speed, acceleration.
fn defaults(kind: JointKind) -> [f64; 4] {
    match kind {
        JointKind::Revolute => {
            let half = std::f64::consts::FRAC_PI_2;
            [-half, half, 1.0, 5.0]
        }
        JointKind::Prismatic => [-0.1, 0.1, 0.2, 1.0],
    }
}
