//! The JSON form of a [`Robot`]: every field as written, with the defaults of a chain (the
//! antecedent is the joint before, `γ = b = 0`), and the checks that turn it into a robot.

use serde::{Deserialize, Deserializer, Serialize};

use crate::robot::{Convention, Joint, JointKind, Placement, Robot};

/// A joint as written in JSON.
#[derive(Clone, Serialize, Deserialize)]
pub(crate) struct RawJoint {
    #[serde(rename = "type")]
    kind: JointKind,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    theta: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    d: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    a: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    alpha: Option<f64>,
    /// Absent: the joint before; `null`: the base; an index: that joint.
    #[serde(
        default,
        deserialize_with = "present",
        skip_serializing_if = "Option::is_none"
    )]
    parent: Option<Option<usize>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    gamma: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    xyz: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    rpy: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    rotation: Option<[[f64; 3]; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    axis: Option<[f64; 3]>,
    mass: f64,
    com: [f64; 3],
    inertia: [f64; 6],
    #[serde(default)]
    actuator_inertia: f64,
    #[serde(default)]
    spring_stiffness: f64,
    #[serde(default)]
    spring_rest: f64,
}

/// A robot as written in JSON.
#[derive(Clone, Serialize, Deserialize)]
pub(crate) struct RawRobot {
    name: String,
    #[serde(default)]
    description: String,
    convention: Convention,
    gravity: [f64; 3],
    joints: Vec<RawJoint>,
}

/// A field that is present, even as `null` (`Some(None)`), against one that is absent (`None`,
/// from `#[serde(default)]`).
fn present<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Option<usize>>, D::Error> {
    Option::<usize>::deserialize(d).map(Some)
}

/// `Rz(yaw) Ry(pitch) Rx(roll)`, URDF's reading of `rpy`, by rows.
fn rpy_rotation([roll, pitch, yaw]: [f64; 3]) -> [[f64; 3]; 3] {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

impl RawJoint {
    /// The joint `i`, the names of its D-H and URDF-style fields checked against `convention`.
    fn joint(self, i: usize, convention: Convention) -> Result<Joint, String> {
        let named = |fields: &[(&str, bool)]| -> Vec<String> {
            fields
                .iter()
                .filter(|(_, given)| *given)
                .map(|(name, _)| format!("`{name}`"))
                .collect()
        };
        let dh = [
            ("theta", self.theta.is_some()),
            ("d", self.d.is_some()),
            ("a", self.a.is_some()),
            ("alpha", self.alpha.is_some()),
            ("gamma", self.gamma.is_some()),
            ("b", self.b.is_some()),
        ];
        let urdf = [
            ("xyz", self.xyz.is_some()),
            ("rpy", self.rpy.is_some()),
            ("rotation", self.rotation.is_some()),
            ("axis", self.axis.is_some()),
        ];
        let (wrong, needed): (Vec<String>, &[(&str, bool)]) = match convention {
            Convention::Urdf => (named(&dh), &[("axis", self.axis.is_some())]),
            Convention::Standard => (
                named(&[&urdf[..], &dh[4..], &[("parent", self.parent.is_some())]].concat()),
                &dh[..4],
            ),
            Convention::Modified => (named(&urdf), &dh[..4]),
        };
        if !wrong.is_empty() {
            let why = match convention {
                Convention::Standard => "a standard D-H table has no antecedent, γ, b or placement: trees need the modified convention",
                Convention::Modified => "a D-H joint has no placement: use the convention \"urdf\"",
                Convention::Urdf => "a URDF-style joint has no D-H values",
            };
            return Err(format!(
                "joint {i}: {} not allowed ({why})",
                wrong.join(", ")
            ));
        }
        if let Some((name, _)) = needed.iter().find(|(_, given)| !given) {
            return Err(format!("joint {i}: missing field `{name}`"));
        }
        if self.rpy.is_some() && self.rotation.is_some() {
            return Err(format!("joint {i}: give `rpy` or `rotation`, not both"));
        }
        let placement = self.axis.map(|axis| Placement {
            rotation: match (self.rotation, self.rpy) {
                (Some(r), _) => r,
                (None, rpy) => rpy_rotation(rpy.unwrap_or_default()),
            },
            xyz: self.xyz.unwrap_or_default(),
            axis,
        });
        Ok(Joint {
            kind: self.kind,
            theta: self.theta.unwrap_or(0.0),
            d: self.d.unwrap_or(0.0),
            a: self.a.unwrap_or(0.0),
            alpha: self.alpha.unwrap_or(0.0),
            parent: self.parent.unwrap_or(i.checked_sub(1)),
            gamma: self.gamma.unwrap_or(0.0),
            b: self.b.unwrap_or(0.0),
            placement,
            mass: self.mass,
            com: self.com,
            inertia: self.inertia,
            actuator_inertia: self.actuator_inertia,
            spring_stiffness: self.spring_stiffness,
            spring_rest: self.spring_rest,
        })
    }
}

impl TryFrom<RawRobot> for Robot {
    type Error = String;

    fn try_from(raw: RawRobot) -> Result<Robot, String> {
        let convention = raw.convention;
        let joints = raw
            .joints
            .into_iter()
            .enumerate()
            .map(|(i, j)| j.joint(i, convention))
            .collect::<Result<Vec<Joint>, String>>()?;
        let robot = Robot {
            name: raw.name,
            description: raw.description,
            convention,
            gravity: raw.gravity,
            joints,
        };
        robot.check()?;
        Ok(robot)
    }
}

impl From<Robot> for RawRobot {
    fn from(robot: Robot) -> RawRobot {
        let dh = robot.convention != Convention::Urdf;
        let modified = robot.convention == Convention::Modified;
        let joints = robot.joints.into_iter().enumerate().map(|(i, j)| {
            let placement = j.placement.as_ref();
            RawJoint {
                kind: j.kind,
                theta: dh.then_some(j.theta),
                d: dh.then_some(j.d),
                a: dh.then_some(j.a),
                alpha: dh.then_some(j.alpha),
                parent: (j.parent != i.checked_sub(1)).then_some(j.parent),
                gamma: (modified && j.gamma != 0.0).then_some(j.gamma),
                b: (modified && j.b != 0.0).then_some(j.b),
                xyz: placement.map(|p| p.xyz),
                rpy: None,
                rotation: placement.map(|p| p.rotation),
                axis: placement.map(|p| p.axis),
                mass: j.mass,
                com: j.com,
                inertia: j.inertia,
                actuator_inertia: j.actuator_inertia,
                spring_stiffness: j.spring_stiffness,
                spring_rest: j.spring_rest,
            }
        });
        RawRobot {
            name: robot.name,
            description: robot.description,
            convention: robot.convention,
            gravity: robot.gravity,
            joints: joints.collect(),
        }
    }
}

// By hand rather than `#[serde(try_from, into)]` on `Robot`, which would make `robot.rs` name
// this module's types while this module builds the robot's.
impl Serialize for Robot {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        RawRobot::from(self.clone()).serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Robot {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Robot, D::Error> {
        let raw = RawRobot::deserialize(deserializer)?;
        Robot::try_from(raw).map_err(serde::de::Error::custom)
    }
}

impl Robot {
    /// Checks joint `i`: its antecedent comes earlier, a standard-convention joint is in a
    /// chain without `γ`, `b`, a D-H joint has no placement, a URDF-style joint has one, with a
    /// unit axis, an orthonormal rotation and zero D-H values.
    pub(crate) fn check_joint(&self, i: usize) -> Result<(), String> {
        let joint = &self.joints[i];
        if let Some(p) = joint.parent.filter(|&p| p >= i) {
            return Err(format!(
                "joint {i}: antecedent (`parent`) {p} does not come before it (joints are numbered so that every antecedent comes earlier)"
            ));
        }
        let dh_values = [
            joint.theta,
            joint.d,
            joint.a,
            joint.alpha,
            joint.gamma,
            joint.b,
        ];
        match (self.convention, &joint.placement) {
            (Convention::Standard, _) if joint.parent != i.checked_sub(1) || joint.gamma != 0.0 || joint.b != 0.0 => Err(format!(
                "joint {i}: an antecedent other than the joint before, γ or b in a standard D-H table (trees need the modified convention)"
            )),
            (Convention::Standard | Convention::Modified, Some(_)) => {
                Err(format!("joint {i}: a placement in a D-H table"))
            }
            (Convention::Urdf, None) => Err(format!("joint {i}: no placement in a URDF-style robot")),
            (Convention::Urdf, Some(_)) if dh_values.iter().any(|&v| v != 0.0) => {
                Err(format!("joint {i}: D-H values in a URDF-style joint"))
            }
            (Convention::Urdf, Some(p)) => {
                let norm = p.axis.iter().map(|x| x * x).sum::<f64>().sqrt();
                // Rows of a rotation are orthonormal: RRᵀ = 1.
                let r = &p.rotation;
                let off = (0..3)
                    .flat_map(|a| (0..3).map(move |b| (a, b)))
                    .map(|(a, b)| {
                        let dot: f64 = (0..3).map(|k| r[a][k] * r[b][k]).sum();
                        (dot - f64::from(u8::from(a == b))).abs()
                    })
                    .fold(0.0, f64::max);
                if (norm - 1.0).abs() > 1e-9 {
                    Err(format!("joint {i}: `axis` {:?} is not of unit length ({norm})", p.axis))
                } else if off > 1e-9 {
                    Err(format!(
                        "joint {i}: `rotation` {r:?} is not a rotation (R Rᵀ differs from 1 by {off:e})"
                    ))
                } else {
                    Ok(())
                }
            }
            _ => Ok(()),
        }
    }
}
