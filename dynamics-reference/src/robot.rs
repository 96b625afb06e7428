//! The robot description: a D-H table with inertial parameters, deserializable from the
//! project's JSON format (`tests/data/reference/robots/*.json`).

use serde::{Deserialize, Serialize};

/// Which form of the Denavit–Hartenberg link matrix the table uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Convention {
    /// Standard D-H (Niku, Paul): `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)`.
    /// Frame `i` is at the end of link `i`; joint `i` moves about/along `z_{i−1}`.
    /// JSON: `"standard"`.
    Standard,
    /// Modified D-H (Craig): `A_i = Rotx(α_{i−1}) Transx(a_{i−1}) Rotz(θ_i) Transz(d_i)`,
    /// where the `a`, `alpha` stored in joint entry `i` are `a_{i−1}`, `α_{i−1}`.
    /// Frame `i` is at joint `i`, which moves about/along `z_i`. JSON: `"modified"`.
    Modified,
}

/// The kind of a joint.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum JointKind {
    /// Revolute joint: the joint variable is the angle, `θ_i = q_i + theta`.
    /// JSON: `"revolute"`.
    Revolute,
    /// Prismatic joint: the joint variable is the offset, `d_i = q_i + d`.
    /// JSON: `"prismatic"`.
    Prismatic,
}

/// One row of the D-H table together with the inertial data of the link it moves.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Joint {
    /// Revolute or prismatic (JSON field `"type"`).
    #[serde(rename = "type")]
    pub kind: JointKind,
    /// D-H angle θ: the offset added to `q` for a revolute joint, the constant angle of a
    /// prismatic joint (rad).
    pub theta: f64,
    /// D-H offset d: the constant offset of a revolute joint, the offset added to `q`
    /// for a prismatic joint (m).
    pub d: f64,
    /// D-H length a (m); `a_{i−1}` in the modified convention.
    pub a: f64,
    /// D-H twist α (rad); `α_{i−1}` in the modified convention.
    pub alpha: f64,
    /// Link mass (kg).
    pub mass: f64,
    /// Centre of mass in link frame `i` (m).
    pub com: [f64; 3],
    /// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`: entries of the inertia **tensor about the centre
    /// of mass** in the axes of frame `i` (kg·m²). Off-diagonal entries are the tensor
    /// entries, i.e. `Ixy = −∫xy dm` (URDF convention), not the book's products of
    /// inertia.
    pub inertia: [f64; 6],
    /// Actuator (motor) inertia `I_i(act)` of eq. (6.39), reflected to the joint (kg·m²
    /// or kg). Defaults to 0.
    #[serde(default)]
    pub actuator_inertia: f64,
    /// Stiffness `k` of a joint spring with potential `½ k (q − rest)²`. Defaults to 0.
    #[serde(default)]
    pub spring_stiffness: f64,
    /// Rest position of the joint spring. Defaults to 0.
    #[serde(default)]
    pub spring_rest: f64,
}

/// A serial robot: D-H table, inertial parameters and gravity.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Robot {
    /// Short name.
    pub name: String,
    /// Free text. Defaults to the empty string.
    #[serde(default)]
    pub description: String,
    /// Standard or modified D-H.
    pub convention: Convention,
    /// Gravity acceleration in the base frame (m/s²), e.g. `[0, 0, −9.81]`.
    pub gravity: [f64; 3],
    /// Joints in order from the base; `joints[0]` is the book's joint 1.
    pub joints: Vec<Joint>,
}

impl Robot {
    /// Parses a robot description in the project's JSON format.
    ///
    /// # Errors
    ///
    /// Returns the `serde_json` error if the text is not valid JSON or does not match
    /// the format (missing field, unknown joint type or convention, wrong array length).
    pub fn from_json(json: &str) -> Result<Robot, serde_json::Error> {
        serde_json::from_str(json)
    }

    /// Number of joints (degrees of freedom) `n`.
    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// Panics with a clear message if a joint-space vector has the wrong length.
    pub(crate) fn check_len(&self, what: &str, v: &[f64]) {
        assert_eq!(
            v.len(),
            self.dof(),
            "{what} has {} entries but robot {:?} has {} joints",
            v.len(),
            self.name,
            self.dof()
        );
    }
}
