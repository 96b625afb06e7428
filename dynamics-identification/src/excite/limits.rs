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

/// Per joint of `robot`, its limits: asked for, else from `urdf` (per joint, if the robot is
/// one), else the defaults.
///
/// # Errors
/// A list whose length is neither 1 nor the joints', an empty range, a speed or acceleration
/// limit that is not positive ([`Error::Setting`]): the option's name and the joint.
pub fn joint_limits(
    robot: &Robot,
    urdf: Option<&[Limit]>,
    asked: Asked,
) -> Result<Vec<JointLimits>, Error> {
    let n = robot.joints.len();
    if let Some((k, list)) = (0..4).find_map(|k| {
        asked[k]
            .filter(|v| v.len() != 1 && v.len() != n)
            .map(|v| (k, v))
    }) {
        return Err(Error::Setting(format!(
            "{}: {} values; give one for every joint or one for each of the {n} joints",
            OPTIONS[k],
            list.len()
        )));
    }
    let mut out = Vec::with_capacity(n);
    for (j, joint) in robot.joints.iter().enumerate() {
        let file = urdf.and_then(|u| u.get(j)).copied().unwrap_or_default();
        // A range only where both ends are written (URDF's default for a missing end is 0).
        let range = match (file.lower, file.upper) {
            (Some(l), Some(u)) if l < u => [Some(l), Some(u)],
            _ => [None, None],
        };
        let from_file = [range[0], range[1], file.velocity.filter(|v| *v > 0.0), None];
        let defaults = defaults(joint.kind);
        let mut values = [0.0; 4];
        let mut origins = [Origin::Default; 4];
        for k in 0..4 {
            let given = asked[k].map(|v| if v.len() == 1 { v[0] } else { v[j] });
            (values[k], origins[k]) = match (given, from_file[k]) {
                (Some(x), _) => (x, Origin::Option),
                (None, Some(x)) => (x, Origin::Urdf),
                (None, None) => (defaults[k], Origin::Default),
            };
        }
        let [lower, upper, velocity, acceleration] = values;
        let joint = j + 1;
        if lower >= upper {
            return Err(Error::Setting(format!(
                "joint {joint}: the range [{lower}, {upper}] is empty (--q-min, --q-max)"
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A revolute and a prismatic joint.
    fn robot() -> Robot {
        let text =
            "name = \"rp\"\ngravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
                    [[joints]]\ntype = \"prismatic\"\nmass = 1\n";
        let source = dynamics_codegen::Source {
            path: "rp.toml",
            text: Some(text),
            ..dynamics_codegen::Source::default()
        };
        dynamics_codegen::load(&source).expect("reads").robot
    }

    #[test]
    fn options_then_the_urdf_then_the_defaults() {
        let half = std::f64::consts::FRAC_PI_2;
        let none = joint_limits(&robot(), None, [None; 4]).expect("defaults");
        assert_eq!(none[0].limits.lower, -half);
        assert_eq!(
            [
                none[1].limits.upper,
                none[1].limits.velocity,
                none[1].limits.acceleration
            ],
            [0.1, 0.2, 1.0]
        );
        assert!(none.iter().all(|j| j.origins == [Origin::Default; 4]));
        // The file: a range on joint 1, only one end on joint 2 (no range), speeds on both.
        let urdf = [
            Limit {
                lower: Some(-2.0),
                upper: Some(3.0),
                velocity: Some(1.5),
                effort: None,
            },
            Limit {
                lower: Some(0.0),
                upper: None,
                velocity: Some(0.3),
                effort: None,
            },
        ];
        let upper = [4.0];
        let accelerations = [2.0, 0.5];
        let asked = [None, Some(&upper[..]), None, Some(&accelerations[..])];
        let got = joint_limits(&robot(), Some(&urdf), asked).expect("limits");
        let want = [
            (
                -2.0,
                4.0,
                1.5,
                2.0,
                [Origin::Urdf, Origin::Option, Origin::Urdf],
            ),
            (
                -0.1,
                4.0,
                0.3,
                0.5,
                [Origin::Default, Origin::Option, Origin::Urdf],
            ),
        ];
        for (j, (lower, upper, velocity, acceleration, origins)) in want.into_iter().enumerate() {
            let l = got[j].limits;
            assert_eq!(
                [l.lower, l.upper, l.velocity, l.acceleration],
                [lower, upper, velocity, acceleration]
            );
            assert_eq!(got[j].origins[..3], origins, "{j}");
            assert_eq!(got[j].origins[3], Origin::Option);
        }
    }
}
