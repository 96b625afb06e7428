//! Joint frames given URDF style, as a fixed placement followed by a motion about or along an
//! axis, and rigid poses between frames.
//!
//! A joint given this way has link frame i = `P_i · Rot(u_i, q_i)` (revolute) or
//! `P_i · Trans(q_i u_i)` (prismatic) in link frame i − 1, with `P_i` the placement
//! `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`. The generator works on the robot's own D-H table,
//! which the front end derives from these frames; [`Pose`]s relate the two.

use super::Value;

/// A fixed placement, as URDF's `<origin xyz rpy>`: `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`
/// with `rpy = [roll, pitch, yaw]` in radians.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Placement {
    /// Translation.
    pub xyz: [Value; 3],
    /// Roll, pitch, yaw about the fixed x, y, z axes.
    pub rpy: [Value; 3],
}

/// Joint i as the user gave it, URDF style: `origin` places the joint frame in link frame
/// i − 1 (the base frame for joint 1), and the joint turns about or slides along the unit
/// `axis`, in joint-frame axes. At q = 0 the joint frame is link frame i, the frame of link
/// i's inertial parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisFrame {
    /// The placement of the joint frame.
    pub origin: Placement,
    /// The unit axis, in the joint frame.
    pub axis: [Value; 3],
}

/// A rigid transform `x ↦ rotation · x + translation` with an exact rotation matrix (rows).
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// The rotation matrix, row by row.
    pub rotation: [[Value; 3]; 3],
    /// The translation.
    pub translation: [Value; 3],
}

impl Pose {
    /// The identity.
    #[must_use]
    pub fn identity() -> Pose {
        let one = || Value::Num(crate::symbolic::Number::ONE);
        Pose {
            rotation: [
                [one(), Value::zero(), Value::zero()],
                [Value::zero(), one(), Value::zero()],
                [Value::zero(), Value::zero(), one()],
            ],
            translation: Default::default(),
        }
    }
}

impl Default for Pose {
    fn default() -> Pose {
        Pose::identity()
    }
}

/// How far from a multiple of π/2 an angle given as a number may be and still be taken as that
/// exact quarter turn, in radians. URDF files write π/2 as 1.5708 (3.7e-6 off) and π as 3.14159
/// (2.7e-6 off), and exporters leave residues such as 1e-15; a turn meant as 0.0001 rad or more
/// is kept.
pub const QUARTER_TURN_TOLERANCE: f64 = 1e-5;

/// The most quarter turns (either way) an angle snaps to: four turns. Larger angles are kept as
/// written (the front ends reject plain numbers above 2π anyway).
pub const MAX_SNAPPED_QUARTER_TURNS: f64 = 16.0;

/// `angle` as an exact multiple of π/2 (`k/2 · π`) if it is a number within
/// [`QUARTER_TURN_TOLERANCE`] of one, at most [`MAX_SNAPPED_QUARTER_TURNS`] quarter turns;
/// otherwise unchanged.
#[must_use]
pub fn snap_angle(angle: &Value) -> Value {
    if angle.pi_multiple().is_some() {
        return angle.clone();
    }
    let Some(x) = angle.exact().map(crate::symbolic::Number::to_f64) else {
        return angle.clone();
    };
    let quarter = std::f64::consts::FRAC_PI_2;
    let k = (x / quarter).round();
    // Far out, a float's spacing exceeds the tolerance and every number would "snap".
    if k.abs() > MAX_SNAPPED_QUARTER_TURNS || (x - k * quarter).abs() > QUARTER_TURN_TOLERANCE {
        return angle.clone();
    }
    #[allow(clippy::cast_possible_truncation)]
    let half_turns = crate::symbolic::Number::ratio(k as i128, 2).expect("a small ratio");
    Value::num(half_turns) * Value::Pi
}

/// `(sin θ, cos θ)` of a constant angle: exact for a multiple of π/2 (after
/// [`snap_angle`]), a float otherwise; `None` for an angle that names a struct field.
#[must_use]
pub fn sin_cos(angle: &Value) -> Option<(Value, Value)> {
    let angle = snap_angle(angle);
    if let Some(k) = angle
        .pi_multiple()
        .and_then(|m| (m * crate::symbolic::Number::int(2)).as_integer())
    {
        let quarter = k.rem_euclid(4);
        let (s, c) = [(0, 1), (1, 0), (0, -1), (-1, 0)][usize::try_from(quarter).ok()?];
        return Some((
            Value::num(crate::symbolic::Number::int(s)),
            Value::num(crate::symbolic::Number::int(c)),
        ));
    }
    let x = angle.eval(&|_| None)?;
    let f = |v: f64| Value::num(crate::symbolic::Number::from_float(v));
    Some((f(x.sin()), f(x.cos())))
}

/// A 3×3 matrix of values, row by row.
pub type Matrix = [[Value; 3]; 3];

/// `a · b`.
#[must_use]
pub fn mat_mul(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).fold(Value::zero(), |acc, k| {
                acc + a[i][k].clone() * b[k][j].clone()
            })
        })
    })
}

/// `a · v`.
#[must_use]
pub fn mat_vec(a: &Matrix, v: &[Value; 3]) -> [Value; 3] {
    std::array::from_fn(|i| {
        (0..3).fold(Value::zero(), |acc, k| acc + a[i][k].clone() * v[k].clone())
    })
}

/// `aᵀ`.
#[must_use]
pub fn transpose(a: &Matrix) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i].clone()))
}

/// The rotation by `(sin, cos)` about axis 0 (x), 1 (y) or 2 (z).
fn axis_rotation(axis: usize, (s, c): (Value, Value)) -> Matrix {
    let (j, k) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut m = Pose::identity().rotation;
    m[j][j] = c.clone();
    m[k][k] = c;
    m[j][k] = -s.clone();
    m[k][j] = s;
    m
}

impl Placement {
    /// A placement as a user writes it: each angle within [`QUARTER_TURN_TOLERANCE`] of a
    /// quarter turn taken as that quarter turn ([`snap_angle`]).
    #[must_use]
    pub fn written(xyz: [Value; 3], rpy: [Value; 3]) -> Self {
        Placement {
            xyz,
            rpy: rpy.map(|angle| snap_angle(&angle)),
        }
    }

    /// The placement as a pose, `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`, angles snapped with
    /// [`snap_angle`]; `Err(i)` if angle `i` (0 roll, 1 pitch, 2 yaw) names a struct field.
    pub fn pose(&self) -> Result<Pose, usize> {
        let rot = |i: usize| {
            sin_cos(&self.rpy[i])
                .map(|sc| axis_rotation(i, sc))
                .ok_or(i)
        };
        let rotation = mat_mul(&rot(2)?, &mat_mul(&rot(1)?, &rot(0)?));
        Ok(Pose {
            rotation,
            translation: self.xyz.clone(),
        })
    }
}

impl Pose {
    /// `self · other`: first `other`, then `self` (frames compose left to right).
    #[must_use]
    pub fn then(&self, other: &Pose) -> Pose {
        let moved = mat_vec(&self.rotation, &other.translation);
        Pose {
            rotation: mat_mul(&self.rotation, &other.rotation),
            translation: std::array::from_fn(|i| moved[i].clone() + self.translation[i].clone()),
        }
    }

    /// The inverse transform: `(Rᵀ, −Rᵀ t)`.
    #[must_use]
    pub fn inverse(&self) -> Pose {
        let rotation = transpose(&self.rotation);
        let back = mat_vec(&rotation, &self.translation);
        Pose {
            rotation,
            translation: back.map(|x| -x),
        }
    }

    /// A point's coordinates mapped: `R p + t`.
    #[must_use]
    pub fn apply(&self, p: &[Value; 3]) -> [Value; 3] {
        let r = mat_vec(&self.rotation, p);
        std::array::from_fn(|i| r[i].clone() + self.translation[i].clone())
    }
}

/// An inertia tensor `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (tensor off-diagonals, as URDF) given in
/// axes B, expressed in axes A where `rotation` maps B coordinates to A: `R I Rᵀ`.
#[must_use]
pub fn rotate_inertia(rotation: &Matrix, inertia: &[Value; 6]) -> [Value; 6] {
    let [xx, yy, zz, xy, xz, yz] = inertia.clone();
    let tensor = [
        [xx, xy.clone(), xz.clone()],
        [xy, yy, yz.clone()],
        [xz, yz, zz],
    ];
    let t = mat_mul(&mat_mul(rotation, &tensor), &transpose(rotation));
    [
        t[0][0].clone(),
        t[1][1].clone(),
        t[2][2].clone(),
        t[0][1].clone(),
        t[0][2].clone(),
        t[1][2].clone(),
    ]
}
