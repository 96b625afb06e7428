//! Forward kinematics, the hand's geometric Jacobians and acceleration bias, and statics
//! (Niku, ch. 6.7), over any [`Scalar`].
//!
//! * **Poses.** D-H frame i in the base frame is `base · A_1 ⋯ A_i` (standard:
//!   `A_i = Rotz(θ_i) Transz(d_i) Transx(a_i) Rotx(α_i)`; modified:
//!   `A_i = Rotx(α_{i−1}) Transx(a_{i−1}) Rotz(θ_i) Transz(d_i)`), the user's link frame i is
//!   that times `link_pose_i`, and the hand frame is link frame n times the tool transform. In
//!   a tree, frame i is its antecedent's times `Rotz(γ_i) Transz(b_i) A_i`, and the hand is
//!   the last joint's link: only that joint and its ancestors move it (the Jacobians' other
//!   columns are zero, and the sums below run over them alone).
//! * **Jacobian in the base frame** (Pinocchio's `LOCAL_WORLD_ALIGNED`): the velocity of the
//!   hand's origin and its angular velocity, in base axes. Column i is `[z_i × (p − o_i); z_i]`
//!   for a revolute joint and `[z_i; 0]` for a prismatic one, with `z_i`, `o_i` the axis and
//!   an origin of joint i (z of D-H frame i − 1 in the standard convention, of frame i in the
//!   modified one) and `p` the hand's origin.
//! * **Jacobian in the hand frame**, the book's ᴴJ (rows dx, dy, dz, δx, δy, δz), by Paul's
//!   method: with `[n o a p]` the hand in joint i's axis frame (the product of the A's from
//!   that frame on), column i is `[−n_x p_y + n_y p_x, −o_x p_y + o_y p_x, −a_x p_y + a_y p_x,
//!   n_z, o_z, a_z]` for a revolute joint and `[n_z, o_z, a_z, 0, 0, 0]` for a prismatic one.
//! * **Acceleration bias** `J̇ q̇` of the base-frame Jacobian (the hand's classical
//!   acceleration at `q̈ = 0`): with `ω_(i) = Σ_{k<i} z_k q̇_k` (revolute k) the angular velocity
//!   of the body carrying axis i, `r_i = p − o_i` and `w_i = Σ_{k≥i} J_v,k q̇_k`,
//!   `d/dt J_v,i = (ω_(i) × z_i) × r_i + z_i × (ω_(i) × r_i + w_i)`, `d/dt J_ω,i = ω_(i) × z_i`
//!   (revolute), `d/dt J_v,i = ω_(i) × z_i` (prismatic). In the hand frame, the same
//!   acceleration in hand axes, `Rᵀ J̇ q̇` (Pinocchio's classical acceleration in `LOCAL`).
//! * **Statics**: `T = Jᵀ F` (eq. 6.64) for a wrench `[f; m]` in the Jacobian's frame, the
//!   moment about the hand's origin.

use super::{JointKind, Mat3, RobotScalars, Scalar, V3};
use crate::model::{Convention, Placement, Pose, Robot, Tip};

/// A rigid transform `x ↦ rotation · x + position`.
#[derive(Clone, Copy, Debug)]
pub struct Frame<S> {
    /// The rotation.
    pub rotation: Mat3<S>,
    /// The position of the origin.
    pub position: V3<S>,
}

impl<S: Scalar> Frame<S> {
    /// `self · other`: `other`, given in `self`, in `self`'s parent.
    #[must_use]
    pub fn then(&self, other: &Frame<S>) -> Frame<S> {
        Frame {
            rotation: self.rotation.mul(&other.rotation),
            position: self.rotation.mul_vec(other.position) + self.position,
        }
    }

    /// The rows `[R | p]`, 3 × 4.
    pub fn rows(&self) -> [[S; 4]; 3] {
        let (r, p) = (&self.rotation.m, self.position);
        [
            [r[0][0], r[0][1], r[0][2], p.x],
            [r[1][0], r[1][1], r[1][2], p.y],
            [r[2][0], r[2][1], r[2][2], p.z],
        ]
    }
}

/// The kinematics of a robot at one position, in the user's base frame.
#[derive(Clone, Debug)]
pub struct Kinematics<S> {
    /// The user's link frame i, for each joint.
    pub links: Vec<Frame<S>>,
    /// The hand (tool) frame.
    pub hand: Frame<S>,
    /// Each joint's kind, unit axis `z_i` and a point `o_i` on its axis.
    pub axes: Vec<(JointKind, V3<S>, V3<S>)>,
    /// For each joint i, the hand in joint i's axis frame (Paul's `[n o a p]`).
    pub hand_from_axis: Vec<Frame<S>>,
    /// Whether joint i moves the hand: it is the last joint or one of its ancestors. The
    /// Jacobians' other columns are zero.
    pub moves_hand: Vec<bool>,
}

/// A 6-row Jacobian, rows `[dx, dy, dz, δx, δy, δz]`, one column per joint.
pub type Jacobian<S> = [Vec<S>; 6];

/// The kinematics of `robot` at the joint variables of `scalars`, its hand at the last joint's
/// link and tool.
pub fn kinematics<R: RobotScalars>(scalars: &mut R, robot: &Robot) -> Kinematics<R::Scalar> {
    kinematics_to(scalars, robot, None)
}

/// The kinematics of `robot` with `tip` for the hand: its frame, and the Jacobians' columns of
/// the joints that carry it.
pub fn tip_kinematics<R: RobotScalars>(
    scalars: &mut R,
    robot: &Robot,
    tip: &Tip,
) -> Kinematics<R::Scalar> {
    kinematics_to(scalars, robot, Some(tip))
}

/// The kinematics with the hand at `tip`, or at the last joint's link and tool. Each value is
/// built in the same order either way, so a robot's graph (and code) does not depend on tips.
fn kinematics_to<R: RobotScalars>(
    scalars: &mut R,
    robot: &Robot,
    tip: Option<&Tip>,
) -> Kinematics<R::Scalar> {
    let zero = scalars.value(&crate::model::Value::zero());
    let base = pose(scalars, &robot.base);
    let tool = match (tip, robot.tool.as_ref()) {
        (Some(tip), _) => pose(scalars, &tip.offset),
        (None, Some(t)) => placement(scalars, t),
        (None, None) => identity(zero),
    };
    let steps: Vec<Frame<R::Scalar>> = (0..robot.dof())
        .map(|i| dh_transform(scalars, robot, i))
        .collect();
    // D-H frame i, from its antecedent's.
    let mut frames: Vec<Frame<R::Scalar>> = Vec::with_capacity(robot.dof());
    let (mut links, mut axes) = (Vec::new(), Vec::new());
    for (i, (joint, step)) in robot.joints.iter().zip(&steps).enumerate() {
        let before = robot.parent(i).map_or(base, |p| frames[p]);
        let frame = before.then(step);
        let axis = match robot.convention {
            Convention::Standard => before,
            Convention::Modified => frame,
        };
        axes.push((joint.kind, column(&axis.rotation, 2), axis.position));
        links.push(frame.then(&pose(scalars, &robot.joints[i].link_pose)));
        frames.push(frame);
    }
    let at = tip.map_or(robot.dof().checked_sub(1), |t| Some(t.joint));
    let last = at.map(|i| pose(scalars, &robot.joints[i].link_pose));
    let end = last.map_or_else(|| identity(zero), |l| l.then(&tool));
    let hand = at.map_or(base, |i| frames[i]).then(&end);
    // Backward, Paul's U: the hand in D-H frame i, from its joint's frame down its ancestors.
    let mut from = end;
    let mut hand_from_axis = vec![end; robot.dof()];
    let mut moves_hand = vec![false; robot.dof()];
    let mut at = at;
    while let Some(i) = at {
        moves_hand[i] = true;
        if robot.convention == Convention::Modified {
            hand_from_axis[i] = from;
        }
        from = steps[i].then(&from);
        if robot.convention == Convention::Standard {
            hand_from_axis[i] = from;
        }
        at = robot.parent(i);
    }
    Kinematics {
        links,
        hand,
        axes,
        hand_from_axis,
        moves_hand,
    }
}

/// The geometric Jacobian of the hand in the base frame (see the module documentation).
pub fn jacobian_in_base<S: Scalar>(k: &Kinematics<S>) -> Jacobian<S> {
    let zero = k.hand.position.x.zero();
    let mut rows: Jacobian<S> = Default::default();
    for (&(kind, z, o), &moves) in k.axes.iter().zip(&k.moves_hand) {
        let (v, w) = match kind {
            _ if !moves => (V3::zero(zero), V3::zero(zero)),
            JointKind::Revolute => (z.cross(k.hand.position - o), z),
            JointKind::Prismatic => (z, V3::zero(zero)),
        };
        for (row, x) in rows.iter_mut().zip([v.x, v.y, v.z, w.x, w.y, w.z]) {
            row.push(x);
        }
    }
    rows
}

/// The book's ᴴJ, by Paul's method (see the module documentation).
pub fn jacobian_in_hand<S: Scalar>(k: &Kinematics<S>) -> Jacobian<S> {
    let mut rows: Jacobian<S> = Default::default();
    for ((&(kind, ..), u), &moves) in k.axes.iter().zip(&k.hand_from_axis).zip(&k.moves_hand) {
        let (r, p) = (&u.rotation.m, u.position);
        let zero = p.x.zero();
        // Column c of the rotation: n, o, a.
        let column = match kind {
            _ if !moves => [zero; 6],
            JointKind::Revolute => {
                let d = |c: usize| r[1][c] * p.x - r[0][c] * p.y;
                [d(0), d(1), d(2), r[2][0], r[2][1], r[2][2]]
            }
            JointKind::Prismatic => [r[2][0], r[2][1], r[2][2], zero, zero, zero],
        };
        for (row, x) in rows.iter_mut().zip(column) {
            row.push(x);
        }
    }
    rows
}

/// `J̇ q̇` of the base-frame Jacobian `jacobian` (see the module documentation).
pub fn acceleration_bias_in_base<S: Scalar>(
    k: &Kinematics<S>,
    jacobian: &Jacobian<S>,
    qd: &[S],
) -> [S; 6] {
    let zero = k.hand.position.x.zero();
    let n = k.axes.len();
    // w_i = Σ_{k≥i} J_v,k q̇_k, from the tip down.
    let mut suffix = vec![V3::zero(zero); n + 1];
    for i in (0..n).rev() {
        let v = V3::new(jacobian[0][i], jacobian[1][i], jacobian[2][i]);
        suffix[i] = suffix[i + 1] + v.scale(qd[i]);
    }
    let (mut linear, mut angular) = (V3::zero(zero), V3::zero(zero));
    let mut omega = V3::zero(zero);
    for (i, &(kind, z, o)) in k.axes.iter().enumerate() {
        if !k.moves_hand[i] {
            continue;
        }
        let z_dot = omega.cross(z);
        match kind {
            JointKind::Revolute => {
                let r = k.hand.position - o;
                let v_dot = z_dot.cross(r) + z.cross(omega.cross(r) + suffix[i]);
                linear = linear + v_dot.scale(qd[i]);
                angular = angular + z_dot.scale(qd[i]);
                omega = omega + z.scale(qd[i]);
            }
            JointKind::Prismatic => linear = linear + z_dot.scale(qd[i]),
        }
    }
    [
        linear.x, linear.y, linear.z, angular.x, angular.y, angular.z,
    ]
}

/// A spatial 6-vector in base axes, `[v; ω]`, in the hand's axes: `[Rᵀ v; Rᵀ ω]`.
pub fn in_hand_axes<S: Scalar>(k: &Kinematics<S>, x: &[S; 6]) -> [S; 6] {
    let r = &k.hand.rotation;
    let v = r.tr_mul_vec(V3::new(x[0], x[1], x[2]));
    let w = r.tr_mul_vec(V3::new(x[3], x[4], x[5]));
    [v.x, v.y, v.z, w.x, w.y, w.z]
}

/// `T = Jᵀ F` (eq. 6.64).
pub fn joint_torques<S: Scalar>(jacobian: &Jacobian<S>, wrench: &[S; 6]) -> Vec<S> {
    (0..jacobian[0].len())
        .map(|j| {
            (1..6).fold(jacobian[0][j] * wrench[0], |sum, i| {
                sum + jacobian[i][j] * wrench[i]
            })
        })
        .collect()
}

/// Column `c` of `m`.
fn column<S: Scalar>(m: &Mat3<S>, c: usize) -> V3<S> {
    V3::new(m.m[0][c], m.m[1][c], m.m[2][c])
}

fn identity<S: Scalar>(zero: S) -> Frame<S> {
    Frame {
        rotation: Mat3::rot_z(zero, zero.one()),
        position: V3::zero(zero),
    }
}

/// `A_i` of joint `i` with its joint variable substituted, in the robot's convention.
fn dh_transform<R: RobotScalars>(scalars: &mut R, robot: &Robot, i: usize) -> Frame<R::Scalar> {
    let row = scalars.dh_row(i, &robot.joints[i]);
    let (st, ct, sa, ca) = (row.sin_theta, row.cos_theta, row.sin_alpha, row.cos_alpha);
    let step = match robot.convention {
        Convention::Standard => Frame {
            rotation: Mat3::rot_z(st, ct).mul(&Mat3::rot_x(sa, ca)),
            position: V3::new(row.a * ct, row.a * st, row.d),
        },
        Convention::Modified => Frame {
            rotation: Mat3::rot_x(sa, ca).mul(&Mat3::rot_z(st, ct)),
            position: V3::new(row.a, -(sa * row.d), ca * row.d),
        },
    };
    match &robot.joints[i].branch {
        Some(branch) => {
            let (sg, cg) = scalars.sin_cos(&branch.gamma);
            let pre = Frame {
                rotation: Mat3::rot_z(sg, cg),
                position: V3::new(sg.zero(), sg.zero(), scalars.value(&branch.b)),
            };
            pre.then(&step)
        }
        None => step,
    }
}

/// A model [`Pose`] as a frame.
fn pose<R: RobotScalars>(scalars: &R, pose: &Pose) -> Frame<R::Scalar> {
    let v = |x| scalars.value(x);
    let t = &pose.translation;
    Frame {
        rotation: Mat3 {
            m: pose.rotation.each_ref().map(|row| row.each_ref().map(v)),
        },
        position: V3::new(v(&t[0]), v(&t[1]), v(&t[2])),
    }
}

/// A [`Placement`], `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`, as a frame.
fn placement<R: RobotScalars>(scalars: &R, p: &Placement) -> Frame<R::Scalar> {
    let [roll, pitch, yaw] = p.rpy.each_ref().map(|a| scalars.sin_cos(a));
    let (sp, cp) = pitch;
    let (o, l) = (sp.zero(), sp.one());
    let rot_y = Mat3 {
        m: [[cp, o, sp], [o, l, o], [-sp, o, cp]],
    };
    let rotation = Mat3::rot_z(yaw.0, yaw.1)
        .mul(&rot_y)
        .mul(&Mat3::rot_x(roll.0, roll.1));
    let v = |x| scalars.value(x);
    Frame {
        rotation,
        position: V3::new(v(&p.xyz[0]), v(&p.xyz[1]), v(&p.xyz[2])),
    }
}
