//! The robot description: a D-H table (or URDF-style placements) with inertial parameters,
//! deserializable from the project's JSON format (`tests/data/reference/robots/*.json`); the
//! JSON form and its checks are in `json.rs`.

use serde::{Deserialize, Serialize};

/// How each joint's frame is given: which form of the Denavit–Hartenberg link matrix the table
/// uses, or URDF-style placements.
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
    ///
    /// Only this convention describes trees (Khalil and Kleinfinger): joint `i` may name its
    /// antecedent ([`Joint::parent`]) and carry `γ`, `b`, and then
    /// `A_i = Rotz(γ_i) Transz(b_i) Rotx(α_i) Transx(a_i) Rotz(θ_i) Transz(d_i)` in the
    /// antecedent's frame.
    Modified,
    /// URDF style: each joint a fixed placement `X_i` in its antecedent's link frame and a unit
    /// axis, `A_i = X_i Rot(axis_i, q_i)` (revolute) or `X_i Trans(axis_i q_i)` (prismatic);
    /// see [`Placement`]. JSON: `"urdf"`.
    Urdf,
}

/// A URDF-style joint: the joint frame's placement in the antecedent's link frame (a URDF
/// `<origin>`) and the unit axis of the joint motion in the joint frame. The link frame is the
/// joint frame moved by the joint; the link's inertial data are given in it.
///
/// JSON (in the joint): `"xyz"` (default 0), one of `"rpy"` (URDF's roll, pitch, yaw, so
/// `R = Rz(yaw) Ry(pitch) Rx(roll)`) or `"rotation"` (the 3×3 matrix by rows; default the
/// identity), and `"axis"` (required, unit length).
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    /// Rotation of the joint frame in the antecedent's link frame, by rows.
    pub rotation: [[f64; 3]; 3],
    /// Origin of the joint frame in the antecedent's link frame (m).
    pub xyz: [f64; 3],
    /// Unit axis of the motion, in the joint frame.
    pub axis: [f64; 3],
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

/// One row of the D-H table (or a URDF-style joint) and its antecedent, together with the
/// inertial data of the link it moves. Its JSON form is in `json.rs`.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Revolute or prismatic (JSON field `"type"`).
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
    /// The antecedent: the index of the joint whose link carries this joint (it must come
    /// earlier), or `None` for the base. JSON `"parent"`: an index, or `null` for the base;
    /// when absent, the joint before (the base for the first joint), as in a chain. Anything
    /// but the joint before needs [`Convention::Modified`] or [`Convention::Urdf`].
    pub parent: Option<usize>,
    /// Khalil and Kleinfinger's γ (rad): the turn about the antecedent's z before the D-H row
    /// ([`Convention::Modified`] only). JSON `"gamma"`, default 0.
    pub gamma: f64,
    /// Khalil and Kleinfinger's b (m): the offset along the antecedent's z before the D-H row
    /// ([`Convention::Modified`] only). JSON `"b"`, default 0.
    pub b: f64,
    /// The joint given URDF style ([`Convention::Urdf`], where it is required and the D-H
    /// values above are 0), or `None` for a D-H row.
    pub placement: Option<Placement>,
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
    pub actuator_inertia: f64,
    /// Stiffness `k` of a joint spring with potential `½ k (q − rest)²`. Defaults to 0.
    pub spring_stiffness: f64,
    /// Rest position of the joint spring. Defaults to 0.
    pub spring_rest: f64,
}

/// A robot: D-H table (or placements), antecedents, inertial parameters and gravity.
///
/// Parsed through the JSON form of `json.rs`, which fills the defaults and refuses what does
/// not describe a robot (an antecedent that does not come earlier, a tree in the standard
/// convention, D-H values on a URDF-style joint, a non-unit axis, a rotation that is not one).
#[derive(Debug, Clone, PartialEq)]
pub struct Robot {
    /// Short name.
    pub name: String,
    /// Free text. Defaults to the empty string.
    pub description: String,
    /// Standard or modified D-H.
    pub convention: Convention,
    /// Gravity acceleration in the base frame (m/s²), e.g. `[0, 0, −9.81]`.
    pub gravity: [f64; 3],
    /// Joints in order from the base, every antecedent before its children; `joints[0]` is
    /// the book's joint 1.
    pub joints: Vec<Joint>,
}

impl Robot {
    /// Parses a robot description in the project's JSON format.
    ///
    /// # Errors
    ///
    /// Returns the `serde_json` error if the text is not valid JSON or does not match
    /// the format (missing field, unknown joint type or convention, wrong array length) or
    /// does not describe a robot (see [`Robot`]).
    pub fn from_json(json: &str) -> Result<Robot, serde_json::Error> {
        serde_json::from_str(json)
    }

    /// Number of joints (degrees of freedom) `n`.
    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// Joint `i`'s antecedent: the joint whose link carries it, or `None` for the base.
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn antecedent(&self, i: usize) -> Option<usize> {
        let parent = self.joints[i].parent;
        if let Some(p) = parent {
            assert!(
                p < i,
                "robot {:?}: joint {i}'s antecedent {p} does not come before it",
                self.name
            );
        }
        parent
    }

    /// Checks what the JSON form checks (see [`Robot`]), for a robot built in code.
    ///
    /// # Errors
    ///
    /// The first problem, naming the joint (0-based) and the field.
    pub fn check(&self) -> Result<(), String> {
        (0..self.dof()).try_for_each(|i| self.check_joint(i))
    }

    /// Whether joint `j` is joint `i` or one of its ancestors, i.e. whether `q_j` moves link
    /// `i` (`U_ij ≠ 0` may hold).
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn moves(&self, j: usize, i: usize) -> bool {
        let mut link = Some(i);
        while let Some(l) = link {
            if l == j {
                return true;
            }
            link = self.antecedent(l);
        }
        false
    }

    /// The joints from the base to joint `i`: its ancestors, then `i` itself.
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn path(&self, i: usize) -> Vec<usize> {
        let mut path = vec![i];
        while let Some(a) = self.antecedent(path[path.len() - 1]) {
            path.push(a);
        }
        path.reverse();
        path
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
