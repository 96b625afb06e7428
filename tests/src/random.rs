//! Random robots and states for property tests, as proptest strategies: [`case`] draws a
//! serial robot (1 to 6 joints, revolute or prismatic, standard or modified D-H, random D-H
//! values with exact 0°/±90°/180° angles and exact zero lengths mixed in, random gravity,
//! physically consistent inertial data, optional actuator inertia and joint springs) and a
//! state `q`, `q̇`, `q̈`. A [`RobotSpec`] holds plain numbers and turns into both the
//! generator's model ([`RobotSpec::model`]) and the independent reference's
//! ([`RobotSpec::reference`]). [`tree`] draws a kinematic tree (2 to 9 joints, each joint's
//! antecedent among the earlier joints or the base, Khalil and Kleinfinger's γ, b and the rest
//! of the row from the same distributions as the chain's), a [`TreeSpec`], and [`tree_case`]
//! adds a state.

use std::f64::consts::{FRAC_PI_2, PI};

use dynamics_codegen::model::{self, Branch, Convention, JointKind, Spring, Value};
use dynamics_codegen::symbolic::Number;
use proptest::collection::vec;
use proptest::prelude::*;

/// A D-H angle: a float, or an exact multiple of π written in one of the two ways the
/// generator recognises.
#[derive(Clone, Copy, Debug)]
pub enum Angle {
    /// Radians.
    Float(f64),
    /// `k · π/2`, stored as the nearest float (as description files store `90 deg`).
    QuarterTurnsFloat(i8),
    /// `num/den · π`, written symbolically: exact sine and cosine for quarter turns, an exact
    /// multiple of π without rational sine and cosine otherwise (30°, 45°, …).
    PiFraction(i8, i8),
}

impl Angle {
    pub fn radians(self) -> f64 {
        match self {
            Angle::Float(x) => x,
            Angle::QuarterTurnsFloat(k) => f64::from(k) * FRAC_PI_2,
            Angle::PiFraction(num, den) => f64::from(num) * PI / f64::from(den),
        }
    }

    pub fn value(self) -> Value {
        match self {
            Angle::Float(x) => Value::from_f64(x),
            Angle::QuarterTurnsFloat(k) => Value::from_f64(f64::from(k) * FRAC_PI_2),
            Angle::PiFraction(num, den) => Value::Mul(
                Box::new(Value::Num(
                    Number::ratio(i128::from(num), i128::from(den)).expect("nonzero denominator"),
                )),
                Box::new(Value::Pi),
            ),
        }
    }
}

/// One joint and its link, in plain numbers.
#[derive(Clone, Debug)]
pub struct JointSpec {
    kind: JointKind,
    theta: Angle,
    d: f64,
    a: f64,
    alpha: Angle,
    mass: f64,
    com: [f64; 3],
    /// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` about the centre of mass.
    inertia: [f64; 6],
    actuator_inertia: f64,
    /// `(stiffness, rest)`.
    spring: Option<(f64, f64)>,
}

/// A robot in plain numbers, turned into both the generator's and the reference's model.
#[derive(Clone, Debug)]
pub struct RobotSpec {
    pub convention: Convention,
    pub gravity: [f64; 3],
    pub joints: Vec<JointSpec>,
}

impl JointSpec {
    /// The generator's joint (a D-H row, in a chain).
    fn model(&self) -> model::Joint {
        let v = Value::from_f64;
        let link = model::Link {
            mass: v(self.mass),
            com: self.com.map(v),
            inertia: self.inertia.map(v),
            actuator_inertia: v(self.actuator_inertia),
            spring: self.spring.map(|(k, rest)| Spring {
                stiffness: v(k),
                rest: v(rest),
            }),
            friction: None,
        };
        let row = [self.theta.value(), v(self.d), v(self.a), self.alpha.value()];
        model::Joint::dh(self.kind, row, link)
    }

    /// The reference's joint, with its antecedent and γ, b.
    fn reference(&self, parent: Option<usize>, gamma: f64, b: f64) -> dynamics_reference::Joint {
        use dynamics_reference as r;
        r::Joint {
            kind: match self.kind {
                JointKind::Revolute => r::JointKind::Revolute,
                JointKind::Prismatic => r::JointKind::Prismatic,
            },
            theta: self.theta.radians(),
            d: self.d,
            a: self.a,
            alpha: self.alpha.radians(),
            parent,
            gamma,
            b,
            placement: None,
            mass: self.mass,
            com: self.com,
            inertia: self.inertia,
            actuator_inertia: self.actuator_inertia,
            spring_stiffness: self.spring.map_or(0.0, |(k, _)| k),
            spring_rest: self.spring.map_or(0.0, |(_, rest)| rest),
        }
    }
}

impl RobotSpec {
    pub fn model(&self) -> model::Robot {
        model::Robot {
            name: "random".into(),
            convention: self.convention,
            gravity: self.gravity.map(Value::from_f64),
            joints: self.joints.iter().map(JointSpec::model).collect(),
            base: model::Pose::identity(),
            tool: None,
            tips: Vec::new(),
        }
    }

    /// The same robot with other physically consistent inertial parameters and actuator
    /// inertias, drawn from `uniform` (numbers in [0, 1)).
    #[must_use]
    pub fn with_inertials(&self, mut uniform: impl FnMut() -> f64) -> RobotSpec {
        let mut robot = self.clone();
        for j in &mut robot.joints {
            j.mass = 0.1 + 5.0 * uniform();
            j.com = [0; 3].map(|_| uniform() - 0.5);
            let [a, b, c] = [0; 3].map(|_| 0.001 + 0.2 * uniform());
            let quaternion = [0; 4].map(|_| 2.0 * uniform() - 1.0);
            j.inertia = rotated_inertia([b + c, a + c, a + b], quaternion);
            j.actuator_inertia = 0.5 * uniform();
        }
        robot
    }

    pub fn reference(&self) -> dynamics_reference::Robot {
        use dynamics_reference as r;
        r::Robot {
            name: "random".into(),
            description: String::new(),
            convention: match self.convention {
                Convention::Standard => r::Convention::Standard,
                Convention::Modified => r::Convention::Modified,
            },
            gravity: self.gravity,
            joints: self
                .joints
                .iter()
                .enumerate()
                .map(|(i, j)| j.reference(i.checked_sub(1), 0.0, 0.0))
                .collect(),
        }
    }
}

/// A joint of a tree: its D-H row and link, its antecedent (`None`: the base) and Khalil and
/// Kleinfinger's γ, b.
#[derive(Clone, Debug)]
pub struct TreeJointSpec {
    pub joint: JointSpec,
    pub parent: Option<usize>,
    pub gamma: Angle,
    pub b: f64,
}

/// A kinematic tree in plain numbers (modified convention), turned into both the generator's
/// model ([`TreeSpec::model`]) and the reference's ([`TreeSpec::reference`]).
#[derive(Clone, Debug)]
pub struct TreeSpec {
    pub gravity: [f64; 3],
    pub joints: Vec<TreeJointSpec>,
}

impl TreeSpec {
    /// The generator's model: every joint with `branch: Some(..)`, the modified convention.
    pub fn model(&self) -> model::Robot {
        model::Robot {
            name: "random tree".into(),
            convention: Convention::Modified,
            gravity: self.gravity.map(Value::from_f64),
            joints: self
                .joints
                .iter()
                .map(|t| model::Joint {
                    branch: Some(Branch {
                        parent: t.parent,
                        gamma: t.gamma.value(),
                        b: Value::from_f64(t.b),
                    }),
                    ..t.joint.model()
                })
                .collect(),
            base: model::Pose::identity(),
            tool: None,
            tips: Vec::new(),
        }
    }

    pub fn reference(&self) -> dynamics_reference::Robot {
        dynamics_reference::Robot {
            name: "random tree".into(),
            description: String::new(),
            convention: dynamics_reference::Convention::Modified,
            gravity: self.gravity,
            joints: self
                .joints
                .iter()
                .map(|t| t.joint.reference(t.parent, t.gamma.radians(), t.b))
                .collect(),
        }
    }

    /// Whether every joint hangs off the one before with `γ = b = 0`: a chain written as a tree.
    pub fn is_chain(&self) -> bool {
        self.joints
            .iter()
            .enumerate()
            .all(|(i, t)| t.parent == i.checked_sub(1) && t.gamma.radians() == 0.0 && t.b == 0.0)
    }
}

/// A tree and a state.
#[derive(Clone, Debug)]
pub struct TreeCase {
    pub tree: TreeSpec,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
}

/// A robot and a state.
#[derive(Clone, Debug)]
pub struct Case {
    pub robot: RobotSpec,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// A random direction in joint space.
    pub x: Vec<f64>,
}

/// An angle: mostly a float in [−π, π), sometimes exactly 0, ±90° or 180° (as a float or
/// symbolically), sometimes a symbolic multiple of π that is not a quarter turn.
pub fn angle() -> impl Strategy<Value = Angle> {
    let quarter_turns = prop_oneof![Just(0i8), Just(1), Just(-1), Just(2)];
    let other_fractions = prop_oneof![Just((1i8, 3i8)), Just((1, 4)), Just((-1, 6)), Just((3, 4))];
    prop_oneof![
        8 => (-PI..PI).prop_map(Angle::Float),
        2 => quarter_turns.clone().prop_map(Angle::QuarterTurnsFloat),
        2 => quarter_turns.prop_map(|k| Angle::PiFraction(k, 2)),
        1 => other_fractions.prop_map(|(num, den)| Angle::PiFraction(num, den)),
    ]
}

/// A length in [−1, 1], sometimes exactly zero.
pub fn length() -> impl Strategy<Value = f64> {
    prop_oneof![3 => -1.0..1.0, 1 => Just(0.0)]
}

/// `R diag(p) Rᵀ` as `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`, with `R` the rotation of the
/// quaternion `w, x, y, z` (normalised; the identity if it is too short).
fn rotated_inertia(p: [f64; 3], [w, x, y, z]: [f64; 4]) -> [f64; 6] {
    let norm = (w * w + x * x + y * y + z * z).sqrt();
    let (w, x, y, z) = if norm < 0.1 {
        (1.0, 0.0, 0.0, 0.0)
    } else {
        (w / norm, x / norm, y / norm, z / norm)
    };
    let r = [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ];
    let entry = |i: usize, j: usize| (0..3).map(|k| r[i][k] * p[k] * r[j][k]).sum::<f64>();
    [
        entry(0, 0),
        entry(1, 1),
        entry(2, 2),
        entry(0, 1),
        entry(0, 2),
        entry(1, 2),
    ]
}

/// A physically consistent inertia tensor about the centre of mass: principal moments
/// `p = (b + c, a + c, a + b)` from positive second moments `a, b, c` (so the triangle
/// inequality holds), in principal axes rotated by a random rotation, or not rotated.
pub fn inertia() -> impl Strategy<Value = [f64; 6]> {
    let second_moments = proptest::array::uniform3(0.001..0.2f64);
    let rotation = prop_oneof![
        1 => Just([1.0, 0.0, 0.0, 0.0]),
        3 => proptest::array::uniform4(-1.0..1.0f64),
    ];
    (second_moments, rotation)
        .prop_map(|([a, b, c], quaternion)| rotated_inertia([b + c, a + c, a + b], quaternion))
}

pub fn joint() -> impl Strategy<Value = JointSpec> {
    let kind = prop_oneof![
        2 => Just(JointKind::Revolute),
        1 => Just(JointKind::Prismatic),
    ];
    let com = proptest::array::uniform3(prop_oneof![3 => -0.5..0.5, 1 => Just(0.0)]);
    let actuator = prop_oneof![Just(0.0), 0.0..0.5];
    let spring = prop_oneof![Just(None), (0.0..20.0, -1.0..1.0).prop_map(Some)];
    (
        kind,
        angle(),
        length(),
        length(),
        angle(),
        0.1..5.0,
        com,
        inertia(),
        actuator,
        spring,
    )
        .prop_map(
            |(kind, theta, d, a, alpha, mass, com, inertia, actuator_inertia, spring)| JointSpec {
                kind,
                theta,
                d,
                a,
                alpha,
                mass,
                com,
                inertia,
                actuator_inertia,
                spring,
            },
        )
}

pub fn robot() -> impl Strategy<Value = RobotSpec> {
    robot_of(1..=6)
}

/// A robot of `joints` joints.
pub fn robot_of(joints: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = RobotSpec> {
    let convention = prop_oneof![Just(Convention::Standard), Just(Convention::Modified)];
    (convention, gravity(), vec(joint(), joints)).prop_map(|(convention, gravity, joints)| {
        RobotSpec {
            convention,
            gravity,
            joints,
        }
    })
}

pub fn case() -> impl Strategy<Value = Case> {
    robot().prop_flat_map(|robot| {
        let n = robot.joints.len();
        (
            Just(robot),
            vec(-PI..PI, n),
            vec(-2.0..2.0, n),
            vec(-2.0..2.0, n),
            vec(-1.0..1.0, n),
        )
            .prop_map(|(robot, q, qd, qdd, x)| Case {
                robot,
                q,
                qd,
                qdd,
                x,
            })
    })
}

/// A gravity: along −z, along −y, or random.
fn gravity() -> impl Strategy<Value = [f64; 3]> {
    prop_oneof![
        1 => Just([0.0, 0.0, -9.81]),
        1 => Just([0.0, -9.81, 0.0]),
        2 => proptest::array::uniform3(-10.0..10.0),
    ]
}

/// A kinematic tree of 2 to 9 joints: joint i's antecedent drawn uniformly among the base and
/// joints 0 … i − 1, γ an [`angle`], b a [`length`], the rest a [`joint`].
pub fn tree() -> impl Strategy<Value = TreeSpec> {
    let joints = vec(
        (joint(), any::<proptest::sample::Index>(), angle(), length()),
        2..=9,
    );
    (gravity(), joints).prop_map(|(gravity, joints)| TreeSpec {
        gravity,
        joints: joints
            .into_iter()
            .enumerate()
            .map(|(i, (joint, index, gamma, b))| TreeJointSpec {
                joint,
                parent: index.index(i + 1).checked_sub(1),
                gamma,
                b,
            })
            .collect(),
    })
}

/// A chain of 2 to 9 joints written as a tree: each joint's antecedent the joint before,
/// `γ = b = 0` (exactly the modified D-H chain).
pub fn chain_as_tree() -> impl Strategy<Value = TreeSpec> {
    (gravity(), vec(joint(), 2..=9)).prop_map(|(gravity, joints)| TreeSpec {
        gravity,
        joints: joints
            .into_iter()
            .enumerate()
            .map(|(i, joint)| TreeJointSpec {
                joint,
                parent: i.checked_sub(1),
                gamma: Angle::Float(0.0),
                b: 0.0,
            })
            .collect(),
    })
}

/// A tree of `trees` and a state.
pub fn tree_case(trees: impl Strategy<Value = TreeSpec>) -> impl Strategy<Value = TreeCase> {
    trees.prop_flat_map(|tree| {
        let n = tree.joints.len();
        (
            Just(tree),
            vec(-PI..PI, n),
            vec(-2.0..2.0, n),
            vec(-2.0..2.0, n),
        )
            .prop_map(|(tree, q, qd, qdd)| TreeCase { tree, q, qd, qdd })
    })
}
