//! Joints given URDF style lowered to the robot's own modified (Craig) D-H table.
//!
//! At q = 0, user link frame i is `L_i = P_1 ⋯ P_i` in the base frame, and joint i's axis is
//! the line through `L_i`'s origin `p_i` along `u_i = R(L_i) · axis_i`. D-H frame i has
//! `z_i = u_i` (so q_i keeps its sign), its origin `o_i` on axis i where the common normal to
//! axis i + 1 meets it, and `x_i` along that normal:
//! - skew or intersecting axes: `x_i = ±(u_i × u_{i+1}) / |u_i × u_{i+1}|`,
//!   `o_i = p_i + s u_i` with `s = (b e − d) / (1 − b²)`, `b = u_i·u_{i+1}`,
//!   `d = u_i·(p_i − p_{i+1})`, `e = u_{i+1}·(p_i − p_{i+1})`;
//! - parallel axes: `o_i` is the foot of the previous normal (d_i = 0, Craig's rule), and
//!   `x_i` the normal from there to axis i + 1, so that offsets along parallel axes collect in
//!   the next d;
//! - the last frame: origin at the foot of the normal from axis n − 1, `x_n = x_{n−1}`
//!   (θ_n offset 0).
//!
//! The sign of `x_i` is the one with `x_{i−1} · x_i ≥ 0`, keeping θ offsets in (−90°, 90°].
//! D-H frame 0 has `z_0 = z_1` (`α_0 = 0`) and its origin at the base frame's, so that the
//! potential energy `−Σ m_i g·c_i` is the same in both frames: `d_1 = o_1·z_1`, and `x_0` along
//! what remains of `o_1` (`a_0` its length; `x_0 = x_1`, `a_0 = 0` where `o_1` lies on the line
//! through the base origin along `z_1`, as for most arms). `Robot::base` is its pose in the base
//! frame (a rotation), and gravity is rewritten into its axes. Then `α_{i−1} = ∠(z_{i−1}, z_i)`
//! about `x_{i−1}`, `a_{i−1} = (o_i − o_{i−1})·x_{i−1}`, `θ_i = ∠(x_{i−1}, x_i)` about `z_i`,
//! `d_i = (o_i − o_{i−1})·z_i`; each link's com and inertia are re-expressed in D-H frame i
//! through `link_pose_i = D_i⁻¹ L_i`.
//!
//! **Trees** (Khalil-Kleinfinger). Joint i hangs from its antecedent p (`Joint::branch`, an
//! earlier joint or the base): `L_i = L_p P_i`. "Axis i + 1" above is axis i's first child's
//! (the first joint in order whose antecedent is i), so a chain lowers as before; a leaf's
//! frame is the last frame's rule, with the normal that reaches it. Each other child k of p
//! (and each root after the first, with D-H frame 0 as antecedent) gets the common normal from
//! axis p to axis k, by the same rules with p's origin as the foot (so `b = 0` where the axes
//! are parallel) and `x_p` as the sign reference (γ in (−90°, 90°]): γ_k turns `x_p` onto it
//! about `z_p`, `b_k` is its foot's offset from `o_p` along `z_p`, and α_k, a_k, θ_k, d_k
//! follow from that turned frame as above. First children get γ = b = 0.

mod geometry;

pub use geometry::NOISE_TOLERANCE;

use super::{rotate_inertia, Convention, Pose, Robot, Value};
use geometry::{
    add, angle, clean, clean3, cross, dot, negate, normalize, number, scale, sub, unit, Vec3,
};

/// How far an axis's length may be from 1 and still be taken as a unit vector (normalized):
/// four-digit URDF axes such as `0.7071 0 0.7071` (length 0.99999) pass.
pub const AXIS_LENGTH_TOLERANCE: f64 = 1e-4;

/// How close an axis component must be to 0 or ±1 to snap to it: the same 1e-5 as an angle's
/// snapping to a quarter turn, since a component of 1e-5 tilts the axis by 1e-5 rad.
pub const AXIS_COMPONENT_TOLERANCE: f64 = super::QUARTER_TURN_TOLERANCE;

/// How small the sine of the angle between two joint axes must be for the axes to be taken as
/// parallel (the common normal then follows Craig's rule for parallel axes): the tilt ignored
/// moves a frame by at most this times the distance between the axes.
pub const PARALLEL_TOLERANCE: f64 = 1e-6;

/// Why a joint given URDF style has no D-H row.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameProblem {
    /// The joint, 0-based.
    pub joint: usize,
    /// The value concerned, for the front ends, which point at it.
    pub part: FramePart,
    /// What is wrong, and what to write instead.
    pub message: String,
}

/// The part of a joint's frame a [`FrameProblem`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FramePart {
    /// Its placement (`xyz`, `rpy`), or the joint as a whole.
    Origin,
    /// Its axis.
    Axis,
}

impl FrameProblem {
    /// Whether the problem is with the joint's axis (rather than its placement).
    #[must_use]
    pub fn concerns_axis(&self) -> bool {
        self.part == FramePart::Axis
    }
}

/// A D-H frame at q = 0, in base coordinates.
#[derive(Clone, Debug)]
struct DhFrame {
    origin: Vec3,
    x: Vec3,
    z: Vec3,
}

impl DhFrame {
    fn pose(&self) -> Pose {
        let y = cross(&self.z, &self.x);
        let columns = [&self.x, &y, &self.z];
        Pose {
            rotation: std::array::from_fn(|r| std::array::from_fn(|c| columns[c][r].clone())),
            translation: self.origin.clone(),
        }
    }
}

/// Joint i's axis at q = 0: a point and a unit direction, in base coordinates, with the user's
/// link frame i.
struct Axis {
    point: Vec3,
    direction: Vec3,
    link: Pose,
}

/// Fills the D-H table of a robot whose joints are given URDF style (`frame: Some(..)`), as the
/// module documentation says; a robot given by its D-H table is left as it is.
///
/// # Errors
/// Every problem found, each naming its joint: a robot mixing D-H rows and frames, a zero or
/// non-unit axis, an angle or axis that names a struct field, an offset between axes that
/// names a struct field in a direction off the coordinate axes.
pub fn lower_frames(robot: &mut Robot) -> Result<(), Vec<FrameProblem>> {
    if robot.joints.iter().all(|j| j.frame.is_none()) {
        return Ok(());
    }
    let parents = parents(robot)?;
    let axes = axes(robot, &parents)?;
    let frames = dh_frames(&axes, &parents)?;
    let base = frames.zero.pose();
    for (i, joint) in robot.joints.iter_mut().enumerate() {
        let antecedent = parents[i].map_or(&frames.zero, |p| &frames.own[p]);
        let (before, frame) = (
            frames.turned[i].as_ref().unwrap_or(antecedent),
            &frames.own[i],
        );
        if let Some(branch) = &mut joint.branch {
            branch.gamma = angle(&antecedent.x, &before.x, &antecedent.z);
            branch.b = dot(&sub(&before.origin, &antecedent.origin), &antecedent.z);
        }
        let step = sub(&frame.origin, &before.origin);
        joint.alpha = angle(&before.z, &frame.z, &before.x);
        joint.a = dot(&step, &before.x);
        joint.theta = angle(&before.x, &frame.x, &frame.z);
        joint.d = dot(&step, &frame.z);
        let link_pose = frame_pose_inverse(frame).then(&axes[i].link);
        joint.link.com = clean3(link_pose.apply(&joint.link.com));
        joint.link.inertia = rotate_inertia(&link_pose.rotation, &joint.link.inertia).map(clean);
        joint.link_pose = clean_pose(link_pose);
    }
    let to_frame_0 = base.inverse();
    robot.gravity = clean3(super::mat_vec(&to_frame_0.rotation, &robot.gravity));
    robot.base = clean_pose(base);
    robot.convention = Convention::Modified;
    Ok(())
}

/// Every joint's antecedent, or a problem for each that is not an earlier joint.
fn parents(robot: &Robot) -> Result<Vec<Option<usize>>, Vec<FrameProblem>> {
    let parents: Vec<Option<usize>> = (0..robot.dof()).map(|i| robot.parent(i)).collect();
    let problems: Vec<FrameProblem> = parents
        .iter()
        .enumerate()
        .filter(|(i, p)| p.is_some_and(|p| p >= *i))
        .map(|(joint, p)| FrameProblem {
            joint,
            part: FramePart::Origin,
            message: format!(
                "its antecedent, joint {}, does not come before it: number the joints so that \
                 each hangs from an earlier one",
                p.map_or(0, |p| p + 1)
            ),
        })
        .collect();
    if problems.is_empty() {
        Ok(parents)
    } else {
        Err(problems)
    }
}

/// D-H frame 0: at the base frame's origin, so that the base pose is a rotation and the
/// potential energy keeps its zero, with `z_0 = z_1`; `x_0` along the offset of D-H frame 1's
/// origin from joint 1's axis direction through the base origin (`x_0 = x_1` where there is
/// none, or where it lies along `x_1`).
fn frame_zero(first: &DhFrame) -> Result<DhFrame, Vec<FrameProblem>> {
    let along = dot(&first.origin, &first.z);
    let off_axis = sub(&first.origin, &scale(&along, &first.z));
    let x = if geometry::is_zero(&off_axis) || geometry::is_zero(&cross(&off_axis, &first.x)) {
        first.x.clone()
    } else {
        let x = direction(&off_axis).ok_or_else(|| {
            vec![FrameProblem {
                joint: 0,
                part: FramePart::Origin,
                message: format!(
                    "its origin's offset from the line through the base origin along its axis, \
                     [{}, {}, {}] in base axes, names struct fields in more than one direction: \
                     write the origin's xyz as numbers, or with the fields along one coordinate \
                     axis",
                    off_axis[0], off_axis[1], off_axis[2]
                ),
            }]
        })?;
        let keeps_x1 = number(&dot(&x, &first.x)).map_or(true, |c| c >= 0.0);
        if keeps_x1 {
            x
        } else {
            negate(&x)
        }
    };
    Ok(DhFrame {
        origin: Default::default(),
        x,
        z: first.z.clone(),
    })
}

fn frame_pose_inverse(frame: &DhFrame) -> Pose {
    frame.pose().inverse()
}

fn clean_pose(pose: Pose) -> Pose {
    Pose {
        rotation: pose.rotation.map(clean3),
        translation: clean3(pose.translation),
    }
}

/// Every joint's axis at q = 0, or every problem with the joints' frames.
fn axes(robot: &Robot, parents: &[Option<usize>]) -> Result<Vec<Axis>, Vec<FrameProblem>> {
    let mut problems = Vec::new();
    // Each joint's user link frame at q = 0 (its antecedent's where the joint has a problem).
    let mut links: Vec<Pose> = Vec::with_capacity(robot.dof());
    let mut axes = Vec::new();
    for (joint, j) in robot.joints.iter().enumerate() {
        let mut link = parents[joint].map_or_else(Pose::identity, |p| links[p].clone());
        links.push(link.clone());
        let mut problem = |part, message: String| {
            problems.push(FrameProblem {
                joint,
                part,
                message,
            });
        };
        let Some(frame) = &j.frame else {
            problem(
                FramePart::Origin,
                "a joint given as a D-H row in a robot whose other joints are given by \
                 placements and axes: give every joint the same way"
                    .into(),
            );
            continue;
        };
        let placement = match frame.origin.pose() {
            Ok(p) => p,
            Err(k) => {
                let name = ["roll", "pitch", "yaw"][k];
                problem(
                    FramePart::Origin,
                    format!(
                        "the {name} angle `{}` names a struct field: the D-H table needs its \
                     value; write it as a number (e.g. `90 deg` or `1.5708`)",
                        frame.origin.rpy[k]
                    ),
                );
                continue;
            }
        };
        link = clean_pose(link.then(&placement));
        links[joint] = link.clone();
        match unit_axis(&frame.axis) {
            Ok(local) => axes.push(Axis {
                point: link.translation.clone(),
                direction: clean3(super::mat_vec(&link.rotation, &local)),
                link: link.clone(),
            }),
            Err(message) => problem(FramePart::Axis, message),
        }
    }
    if problems.is_empty() {
        Ok(axes)
    } else {
        Err(problems)
    }
}

/// The joint's axis as a unit vector: components within [`AXIS_COMPONENT_TOLERANCE`] of 0 or
/// ±1 snapped, then normalized; an error if it names a field, is zero, or its length is off 1
/// by more than [`AXIS_LENGTH_TOLERANCE`].
fn unit_axis(axis: &[Value; 3]) -> Result<Vec3, String> {
    let Some(components) = axis.iter().map(number).collect::<Option<Vec<f64>>>() else {
        return Err(format!(
            "the axis [{}, {}, {}] names a struct field: write it as numbers",
            axis[0], axis[1], axis[2]
        ));
    };
    let length = components.iter().map(|x| x * x).sum::<f64>().sqrt();
    if length <= AXIS_LENGTH_TOLERANCE {
        return Err(
            "the axis is zero: give the unit vector the joint turns about or slides \
                    along, e.g. `[0, 0, 1]`"
                .into(),
        );
    }
    if (length - 1.0).abs() > AXIS_LENGTH_TOLERANCE {
        return Err(format!(
            "the axis has length {length}, not 1 (within {AXIS_LENGTH_TOLERANCE}): write a unit \
             vector, e.g. each component divided by {length}"
        ));
    }
    let snapped: Vec3 = std::array::from_fn(|k| {
        let x = components[k];
        [0.0, 1.0, -1.0]
            .into_iter()
            .find(|e| (x - e).abs() <= AXIS_COMPONENT_TOLERANCE)
            .map_or_else(|| axis[k].clone(), Value::from_f64)
    });
    normalize(&snapped).ok_or_else(|| "the axis snaps to zero".into())
}

/// The D-H frames at q = 0: frame 0, each joint's, and for a joint that is not its
/// antecedent's first child, the antecedent's frame turned by γ about its z and moved by b
/// along it onto the common normal to the joint's axis.
struct Frames {
    zero: DhFrame,
    own: Vec<DhFrame>,
    turned: Vec<Option<DhFrame>>,
}

/// The D-H frames at q = 0, in the joints' order (each antecedent before its children).
fn dh_frames(axes: &[Axis], parents: &[Option<usize>]) -> Result<Frames, Vec<FrameProblem>> {
    let problem = |joint, message| {
        vec![FrameProblem {
            joint,
            part: FramePart::Origin,
            message,
        }]
    };
    let mut first_child: Vec<Option<usize>> = vec![None; axes.len()];
    for (c, parent) in parents.iter().enumerate() {
        if let Some(p) = *parent {
            first_child[p].get_or_insert(c);
        }
    }
    let mut own: Vec<DhFrame> = Vec::with_capacity(axes.len());
    let mut turned = vec![None; axes.len()];
    let mut zero: Option<DhFrame> = None;
    // Per joint, where its frame's x (the normal to its first child) meets that child's axis.
    let mut feet: Vec<Option<Vec3>> = vec![None; axes.len()];
    for (j, axis) in axes.iter().enumerate() {
        // The normal that reaches this axis: the foot on it, and its direction.
        let (foot, incoming_x) = match (parents[j], zero.as_ref()) {
            (Some(p), _) if first_child[p] == Some(j) => (feet[p].clone(), Some(own[p].x.clone())),
            (None, None) => (None, None),
            (parent, zero) => {
                let antecedent =
                    parent.map_or_else(|| zero.expect("joint 1 is a root"), |p| &own[p]);
                let line = Axis {
                    point: antecedent.origin.clone(),
                    direction: antecedent.z.clone(),
                    link: Pose::identity(),
                };
                let normal =
                    common_normal(&line, axis, Some(&antecedent.origin), Some(&antecedent.x))
                        .map_err(|message| problem(j, message))?;
                let (foot, x) = (foot_on(&normal, axis), normal.x.clone());
                turned[j] = Some(normal);
                (Some(foot), Some(x))
            }
        };
        let frame = match first_child[j] {
            None => DhFrame {
                origin: foot.unwrap_or_else(|| axis.point.clone()),
                x: incoming_x.unwrap_or_else(|| perpendicular(axis)),
                z: axis.direction.clone(),
            },
            Some(c) => common_normal(axis, &axes[c], foot.as_ref(), incoming_x.as_ref())
                .map_err(|message| problem(c, message))?,
        };
        feet[j] = first_child[j].map(|c| foot_on(&frame, &axes[c]));
        own.push(frame);
        if j == 0 {
            zero = Some(frame_zero(&own[0])?);
        }
    }
    Ok(Frames {
        zero: zero.expect("a robot lowered has joints"),
        own,
        turned,
    })
}

/// Where the x axis of `frame`, the common normal to `next`'s axis, meets that axis.
fn foot_on(frame: &DhFrame, next: &Axis) -> Vec3 {
    let a = dot(&sub(&next.point, &frame.origin), &frame.x);
    add(&frame.origin, &scale(&a, &frame.x))
}

/// D-H frame i from axes i and i + 1; `foot` is where the previous normal meets axis i, and
/// `previous_x` the previous frame's x (which picks the sign of this one's).
fn common_normal(
    axis: &Axis,
    next: &Axis,
    foot: Option<&Vec3>,
    previous_x: Option<&Vec3>,
) -> Result<DhFrame, String> {
    let (u, v) = (&axis.direction, &next.direction);
    let normal = cross(u, v);
    let reference = previous_x.cloned().unwrap_or_else(|| link_x(axis));
    let (origin, x) = if nearly_parallel(&normal) {
        let origin = foot.cloned().unwrap_or_else(|| axis.point.clone());
        let w = sub(&next.point, &origin);
        let offset = sub(&w, &scale(&dot(&w, u), u));
        let x = if geometry::is_zero(&offset) {
            previous_x.cloned().unwrap_or_else(|| perpendicular(axis))
        } else {
            direction(&offset).ok_or_else(|| {
                format!(
                    "its axis is parallel to the previous joint's, and the offset between them, \
                     [{}, {}, {}] in base axes, names a struct field in a direction off the \
                     coordinate axes: write the origin's xyz as numbers, or with the field in \
                     one component along the offset",
                    offset[0], offset[1], offset[2]
                )
            })?
        };
        (origin, x)
    } else {
        let x = normalize(&normal).expect("directions are numbers");
        let w = sub(&axis.point, &next.point);
        let (b, d, e) = (dot(u, v), dot(u, &w), dot(v, &w));
        let scale_by = (Value::one() - b.clone() * b.clone())
            .exact()
            .and_then(crate::symbolic::Number::recip)
            .expect("directions are numbers, not nearly parallel");
        let s = clean((b * e - d) * Value::num(scale_by));
        (add(&axis.point, &scale(&s, u)), x)
    };
    let x = if number(&dot(&x, &reference)).is_some_and(|c| c < 0.0) {
        negate(&x)
    } else {
        x
    };
    Ok(DhFrame {
        origin,
        x,
        z: u.clone(),
    })
}

/// Whether two unit directions whose cross product is `normal` are parallel for the common
/// normal: exactly, or within [`PARALLEL_TOLERANCE`]: nearer, the skew foot
/// `s = (b e − d) / (1 − b²)` is far off and loses more to rounding than the tilt ignored.
fn nearly_parallel(normal: &Vec3) -> bool {
    geometry::is_zero(normal)
        || number(&dot(normal, normal)).is_some_and(|sin2| sin2 <= PARALLEL_TOLERANCE.powi(2))
}

/// The unit direction of an offset: the coordinate axis it lies along (any component may name
/// fields), or the normalized vector of numbers; `None` otherwise.
fn direction(offset: &Vec3) -> Option<Vec3> {
    let nonzero: Vec<usize> = (0..3).filter(|&k| !offset[k].is_zero()).collect();
    if let [k] = nonzero[..] {
        return Some(unit(k));
    }
    normalize(offset)
}

/// The user's link x axis in base coordinates.
fn link_x(axis: &Axis) -> Vec3 {
    std::array::from_fn(|r| axis.link.rotation[r][0].clone())
}

/// A unit vector perpendicular to the axis: the user's link axis most nearly so, made
/// perpendicular.
fn perpendicular(axis: &Axis) -> Vec3 {
    let u = &axis.direction;
    let candidates: [Vec3; 3] =
        std::array::from_fn(|c| std::array::from_fn(|r| axis.link.rotation[r][c].clone()));
    let best = candidates
        .iter()
        .min_by(|a, b| {
            let along = |v: &Vec3| number(&dot(v, u)).map_or(1.0, f64::abs);
            along(a).total_cmp(&along(b))
        })
        .expect("three candidates");
    let projected = sub(best, &scale(&dot(best, u), u));
    normalize(&projected).expect("directions are numbers")
}
