//! The robot as the generator sees it: a D-H table and link parameters whose values are exact
//! literals or expressions over struct fields. Data types only, free of syn: the front end
//! (attributes or description files) produces them, the checks, the derivation and the
//! command-line tool read them.
//!
//! Joint i moves link i by `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)` (standard D-H)
//! or `A_i = Rotx(α_{i−1}) Transx(a_{i−1}) Rotz(θ_i) Transz(d_i)` (modified D-H).

mod arith;
mod envelope;
mod floating;
mod frame;
mod lower;
mod tip;
mod value;

pub use envelope::{Envelope, JointEnvelope, Simplification};
pub use floating::FreeFlyer;
pub use frame::{
    mat_mul, mat_vec, rotate_inertia, sin_cos, snap_angle, transpose, AxisFrame, Matrix, Placement,
    Pose, MAX_SNAPPED_QUARTER_TURNS, QUARTER_TURN_TOLERANCE,
};
pub use lower::{
    lower_frames, FramePart, FrameProblem, AXIS_COMPONENT_TOLERANCE, AXIS_LENGTH_TOLERANCE,
    NOISE_TOLERANCE, PARALLEL_TOLERANCE,
};
pub use tip::Tip;
pub use value::Value;

/// Revolute or prismatic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum JointKind {
    /// Rotates about its axis: q = θ.
    Revolute,
    /// Slides along its axis: q = d.
    Prismatic,
}

/// Which D-H convention a table uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Convention {
    /// Niku, Paul: `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)`.
    Standard,
    /// Craig: `A_i = Rotx(α_{i−1}) Transx(a_{i−1}) Rotz(θ_i) Transz(d_i)`, with `a_{i−1}`,
    /// `α_{i−1}` stored in row i.
    Modified,
}

/// A joint spring with potential `½ k (q − rest)²`.
#[derive(Clone, Debug, PartialEq)]
pub struct Spring {
    /// Stiffness k.
    pub stiffness: Value,
    /// Rest position.
    pub rest: Value,
}

/// Joint friction: `τ_f = viscous · q̇ + coulomb · sign(q̇) + offset`, with `sign(q̇)` replaced
/// by `tanh(q̇ / smoothing)` where a smoothing velocity is given; `sign(0) = 0`. The torque
/// opposes the motion for non-negative coefficients (the checks refuse negative literals).
/// URDF's `<dynamics damping="…" friction="…"/>` gives `viscous` and `coulomb`.
#[derive(Clone, Debug, PartialEq)]
pub struct Friction {
    /// Viscous coefficient f_v.
    pub viscous: Value,
    /// Coulomb coefficient f_c.
    pub coulomb: Value,
    /// Constant offset.
    pub offset: Value,
    /// Velocity scale ε of the smooth Coulomb term, if any.
    pub smoothing: Option<Value>,
}

impl Friction {
    /// Its values: viscous, Coulomb, offset, then the smoothing velocity if given.
    pub fn values(&self) -> impl Iterator<Item = &Value> {
        [&self.viscous, &self.coulomb, &self.offset]
            .into_iter()
            .chain(self.smoothing.as_ref())
    }
}

/// Link i: its rigid body and what its joint's drive adds. Kept apart from the joint's
/// geometry so that every front end fills it the same way, whatever gives the joint.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Link {
    /// Mass of link i.
    pub mass: Value,
    /// Centre of mass in link frame i.
    pub com: [Value; 3],
    /// Inertia tensor about the centre of mass, axes of frame i: `[Ixx, Iyy, Izz, Ixy, Ixz,
    /// Iyz]`, off-diagonal entries `−∫xy dm` (as URDF).
    pub inertia: [Value; 6],
    /// Actuator inertia I_i(act) (eq. 6.39), added to `M_ii`.
    pub actuator_inertia: Value,
    /// Optional joint spring.
    pub spring: Option<Spring>,
    /// Optional joint friction.
    pub friction: Option<Friction>,
}

impl Link {
    /// Its values: mass, actuator inertia, centre of mass, inertia, spring, friction.
    pub fn values(&self) -> impl Iterator<Item = &Value> {
        [&self.mass, &self.actuator_inertia]
            .into_iter()
            .chain(self.com.iter())
            .chain(self.inertia.iter())
            .chain(self.spring.iter().flat_map(|s| [&s.stiffness, &s.rest]))
            .chain(self.friction.iter().flat_map(Friction::values))
    }
}

/// Joint i and link i.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// Revolute (q = θ − offset) or prismatic (q = d − offset).
    pub kind: JointKind,
    /// θ: the offset added to q for a revolute joint, the constant angle for a prismatic one.
    pub theta: Value,
    /// d: the offset added to q for a prismatic joint, the constant length for a revolute one.
    pub d: Value,
    /// a.
    pub a: Value,
    /// α.
    pub alpha: Value,
    /// Link i, which the joint moves; its inertial parameters are in D-H frame i.
    pub link: Link,
    /// The joint as the user gave it, if not as a D-H row; the D-H columns above then hold the
    /// robot's own table derived from it.
    pub frame: Option<AxisFrame>,
    /// The user's link frame i in D-H frame i (the identity for a robot given by its D-H
    /// table); the inertial parameters above are in D-H frame i.
    pub link_pose: Pose,
    /// Where joint i hangs in a kinematic tree; `None` in a serial chain, where joint i's
    /// antecedent is joint i − 1 and its frame follows from that joint's alone.
    pub branch: Option<Branch>,
    /// The joint this one follows, if it is a mimic joint: then it is not a coordinate of the
    /// robot (see [`Robot::coordinates`]).
    pub mimic: Option<Mimic>,
}

/// A mimic joint's rule: it follows `q = multiplier · q_joint + offset` (URDF's `<mimic>`), so
/// that `q̇ = multiplier · q̇_joint` and `q̈ = multiplier · q̈_joint`; its torque is carried onto
/// the joint it follows.
#[derive(Clone, Debug, PartialEq)]
pub struct Mimic {
    /// The joint followed, in [`Robot::joints`]; not itself a mimic joint.
    pub joint: usize,
    /// k.
    pub multiplier: Value,
    /// o, in the joint's unit (rad or m).
    pub offset: Value,
}

/// A joint's place in a kinematic tree (Khalil and Kleinfinger's modified D-H table): its
/// antecedent, and the turn γ and offset b about and along the antecedent's z that carry the
/// antecedent's frame onto the common normal to this joint's axis. The joint's frame is then
/// `Rotz(γ) Transz(b) Rotx(α) Transx(a) Rotz(θ) Transz(d)` in its antecedent's (with γ = b = 0
/// this is the modified D-H row).
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    /// The antecedent joint, earlier in [`Robot::joints`], or `None` for the base.
    pub parent: Option<usize>,
    /// γ.
    pub gamma: Value,
    /// b.
    pub b: Value,
}

impl Joint {
    /// A joint given by its D-H row `[θ, d, a, α]`.
    #[must_use]
    pub fn dh(kind: JointKind, [theta, d, a, alpha]: [Value; 4], link: Link) -> Joint {
        Joint {
            kind,
            theta,
            d,
            a,
            alpha,
            link,
            frame: None,
            link_pose: Pose::identity(),
            branch: None,
            mimic: None,
        }
    }

    /// A joint given by its frame: its D-H row is derived by [`lower_frames`].
    #[must_use]
    pub fn framed(kind: JointKind, frame: AxisFrame, link: Link) -> Joint {
        Joint {
            frame: Some(frame),
            ..Joint::dh(kind, Default::default(), link)
        }
    }
}

/// A serial robot.
#[derive(Clone, Debug, PartialEq)]
pub struct Robot {
    /// Name, for documentation.
    pub name: String,
    /// D-H convention of the table.
    pub convention: Convention,
    /// Gravity acceleration in the base frame, e.g. `[0, 0, −9.81]`.
    pub gravity: [Value; 3],
    /// Joints, base to tip.
    pub joints: Vec<Joint>,
    /// D-H frame 0 in the user's base frame (the identity for a robot given by its D-H table).
    pub base: Pose,
    /// The tool (hand) frame in the user's link frame n, if one is declared.
    pub tool: Option<Placement>,
    /// The tips the description names (a URDF's), in order; empty where it names none (see
    /// [`Robot::tip_frames`]).
    pub tips: Vec<Tip>,
}

impl Robot {
    /// Number of joints, mimic joints included (see [`Robot::coordinates`]).
    #[must_use]
    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// The robot's coordinates: its joints that are not mimic joints, in order. Every
    /// generated function's q, q̇, q̈ and τ have one entry per coordinate.
    #[must_use]
    pub fn coordinates(&self) -> Vec<usize> {
        (0..self.dof())
            .filter(|&i| self.joints[i].mimic.is_none())
            .collect()
    }

    /// Whether some joint follows another.
    #[must_use]
    pub fn has_mimics(&self) -> bool {
        self.joints.iter().any(|j| j.mimic.is_some())
    }

    /// Joint i's antecedent: the joint whose link carries it, or `None` for the base.
    #[must_use]
    pub fn parent(&self, i: usize) -> Option<usize> {
        match &self.joints[i].branch {
            Some(branch) => branch.parent,
            None => i.checked_sub(1),
        }
    }

    /// Whether some joint's antecedent is not the joint before it: the robot branches (a joint
    /// carries two or more, or two hang off the base).
    #[must_use]
    pub fn is_tree(&self) -> bool {
        (0..self.dof()).any(|i| self.parent(i) != i.checked_sub(1))
    }

    /// Every value of the robot, in a fixed order.
    pub fn values(&self) -> impl Iterator<Item = &Value> {
        self.gravity
            .iter()
            .chain(self.joints.iter().flat_map(|j| {
                [&j.theta, &j.d, &j.a, &j.alpha]
                    .into_iter()
                    .chain(j.branch.iter().flat_map(|b| [&b.gamma, &b.b]))
                    .chain(j.mimic.iter().flat_map(|m| [&m.multiplier, &m.offset]))
                    .chain(j.link.values())
            }))
            .chain(
                self.tool
                    .iter()
                    .flat_map(|t| t.xyz.iter().chain(t.rpy.iter())),
            )
    }

    /// The struct fields that the robot's values name, sorted and without repetition.
    #[must_use]
    pub fn fields(&self) -> Vec<String> {
        let mut names = std::collections::BTreeSet::new();
        for v in self.values() {
            v.collect_fields(&mut names);
        }
        names.into_iter().collect()
    }
}
