//! The chain or tree as the generator's [`Robot`]: one joint per moving URDF joint, given by
//! its frame (placement and axis, in the frame of the link it hangs from) and its antecedent
//! (the moving joint above it, in a tree), its link the rigid body of the joint's child link
//! and every link fixed to it (`inertial`), and its `<dynamics>` as friction. Fixed joints
//! before a moving joint fold into its placement.

use super::inertial::Body;
use super::tree::{Chain, Tree};
use super::xml::{error, Joint as UrdfJoint, Kind};
use crate::check;
use crate::front::errors::FileError;
use crate::front::sources::At;
use crate::model::{
    AxisFrame, Branch, Convention, Friction, Joint, JointKind, Link, Placement, Pose, Robot, Tip,
    Value, AXIS_LENGTH_TOLERANCE,
};
use std::collections::BTreeMap;

/// Where one joint's values are written, by key (`type`, `axis`, `mass`, `inertia`).
type JointPositions = BTreeMap<String, At>;

/// A moving joint with the links it carries, each with its pose in the joint's child frame.
struct Segment {
    joint: usize,
    /// The segment it hangs from, or `None` for the base.
    parent: Option<usize>,
    placement: Placement,
    parts: Vec<(usize, Pose)>,
}

/// The robot of `chain`, gravity `[0, 0, −9.81]`, with where each joint's values are written.
pub(super) fn build(
    tree: &Tree,
    chain: &Chain,
    name: String,
    check_inertia: bool,
) -> Result<(Robot, Vec<JointPositions>), Vec<FileError>> {
    let mut errors = Vec::new();
    let mut joints = Vec::new();
    let mut positions = Vec::new();
    let (segments, tip) = segments(tree, chain);
    let tips = tips(tree, chain, &segments);
    let parents: Vec<Option<usize>> = segments.iter().map(|s| s.parent).collect();
    let urdf_joints: Vec<usize> = segments.iter().map(|s| s.joint).collect();
    for segment in segments {
        errors.extend(link_problems(tree, &segment, check_inertia));
        match joint(tree, segment) {
            Ok((joint, at)) => {
                joints.push(joint);
                positions.push(at);
            }
            Err(e) => errors.extend(e),
        }
    }
    if errors.is_empty() {
        errors = super::mimic::resolve(tree.doc, &urdf_joints, &mut joints);
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    if (0..parents.len()).any(|i| parents[i] != i.checked_sub(1)) {
        for (joint, parent) in joints.iter_mut().zip(parents) {
            joint.branch = Some(Branch {
                parent,
                gamma: Value::zero(),
                b: Value::zero(),
            });
        }
    }
    let number =
        |text| crate::symbolic::Number::parse_decimal(text).map_or_else(Value::zero, Value::num);
    let robot = Robot {
        name,
        convention: Convention::Modified,
        gravity: [number("0"), number("0"), number("-9.81")],
        joints,
        base: Pose::identity(),
        tool: (tip != Pose::identity()).then(|| Placement {
            xyz: tip.translation.clone(),
            rpy: rpy_of(&tip.rotation),
        }),
        tips,
    };
    Ok((robot, positions))
}

/// The moving joints kept, in the chain's order, each with the links fixed to its child link
/// and the segment it hangs from; and the hand's tool transform: the pose of the last tip link
/// that hangs from the last moving joint, in that joint's child frame.
fn segments(tree: &Tree, chain: &Chain) -> (Vec<Segment>, Pose) {
    let mut segments: Vec<Segment> = Vec::new();
    // Per link reached: the segment it belongs to (`None` for the base's body) and its pose
    // in that segment's child frame (or the base's).
    let mut reached = BTreeMap::from([(chain.base, (None, Pose::identity()))]);
    let kept: std::collections::BTreeSet<usize> = chain.joints.iter().copied().collect();
    for &j in &chain.joints {
        let joint = &tree.doc.joints[j];
        let Some((segment, pose)) = reached.get(&tree.parent_link(j)).cloned() else {
            continue;
        };
        let (segment, pose) = if joint.kind.moves() {
            segments.push(Segment {
                joint: j,
                parent: segment,
                placement: compose(&pose, &joint.origin),
                parts: Vec::new(),
            });
            (Some(segments.len() - 1), Pose::identity())
        } else {
            (segment, pose.then(&placement_pose(&joint.origin)))
        };
        let link = tree.child(j);
        if let Some(s) = segment {
            attach(tree, link, pose.clone(), &kept, &mut segments[s].parts);
        }
        reached.insert(link, (segment, pose));
    }
    let last = segments.len().checked_sub(1);
    let tool = chain.tips.iter().rev().find_map(|tip| {
        let (segment, pose) = reached.get(tip)?;
        (*segment == last).then(|| pose.clone())
    });
    (segments, tool.unwrap_or_default())
}

/// The tips: the links `chain` names, each on the segment whose body it is part of (a link
/// fixed to the base has none, and is left out), else the leaf segments' child links.
fn tips(tree: &Tree, chain: &Chain, segments: &[Segment]) -> Vec<Tip> {
    let named = |link: usize| tree.doc.links[link].name.clone();
    if chain.tips.is_empty() {
        let carries = |s: usize| segments.iter().any(|c| c.parent == Some(s));
        return (0..segments.len())
            .filter(|&s| !carries(s))
            .map(|joint| Tip {
                name: named(tree.child(segments[joint].joint)),
                joint,
                offset: Pose::identity(),
            })
            .collect();
    }
    let part_of = |link: usize| {
        segments.iter().enumerate().find_map(|(s, segment)| {
            let (_, pose) = segment.parts.iter().find(|(l, _)| *l == link)?;
            Some((s, pose.clone()))
        })
    };
    chain
        .tips
        .iter()
        .filter_map(|&link| {
            let (joint, offset) = part_of(link)?;
            Some(Tip {
                name: named(link),
                joint,
                offset,
            })
        })
        .collect()
}

/// Adds `link` at `pose` and every link fixed to it, except through the joints `kept` (walked
/// on their own) and moving joints: past a tip, a part fixed to the tip link (a hand) is
/// merged into it and what moves (its fingers) is cut off, as a tool is mounted on a flange.
fn attach(
    tree: &Tree,
    link: usize,
    pose: Pose,
    kept: &std::collections::BTreeSet<usize>,
    parts: &mut Vec<(usize, Pose)>,
) {
    let mut stack = vec![(link, pose)];
    while let Some((link, pose)) = stack.pop() {
        for &j in tree.children(link) {
            if !kept.contains(&j) && !tree.doc.joints[j].kind.moves() {
                let origin = placement_pose(&tree.doc.joints[j].origin);
                stack.push((tree.child(j), pose.then(&origin)));
            }
        }
        parts.push((link, pose));
    }
}

/// A placement's pose; URDF angles are numbers, so it always has one.
fn placement_pose(placement: &Placement) -> Pose {
    placement.pose().unwrap_or_default()
}

/// `origin` after `pose`, as one placement: exact where `pose` does not turn (the fixed joints
/// of the test robots), its angles recovered in floating point otherwise.
fn compose(pose: &Pose, origin: &Placement) -> Placement {
    let identity = Pose::identity();
    if pose.rotation == identity.rotation {
        let xyz = std::array::from_fn(|i| pose.translation[i].clone() + origin.xyz[i].clone());
        return Placement {
            xyz,
            rpy: origin.rpy.clone(),
        };
    }
    let total = pose.then(&placement_pose(origin));
    Placement {
        xyz: total.translation.clone(),
        rpy: rpy_of(&total.rotation),
    }
}

/// `[roll, pitch, yaw]` of `R = Rz(yaw) Ry(pitch) Rx(roll)`; roll 0 at pitch ±π/2.
fn rpy_of(rotation: &[[Value; 3]; 3]) -> [Value; 3] {
    let r = |i: usize, j: usize| rotation[i][j].eval(&|_| None).unwrap_or_default();
    let pitch = (-r(2, 0)).atan2(r(0, 0).hypot(r(1, 0)));
    let (roll, yaw) = if r(0, 0).hypot(r(1, 0)) < 1e-12 {
        (0.0, (-r(0, 1)).atan2(r(1, 1)))
    } else {
        (r(2, 1).atan2(r(2, 2)), r(1, 0).atan2(r(0, 0)))
    };
    [roll, pitch, yaw].map(Value::from_f64)
}

/// The physical problems of every link of `segment`, at the link's `<mass>` or `<inertia>`.
fn link_problems<'a>(
    tree: &'a Tree,
    segment: &'a Segment,
    check_inertia: bool,
) -> impl Iterator<Item = FileError> + 'a {
    segment.parts.iter().flat_map(move |(link, _)| {
        let link = &tree.doc.links[*link];
        let problems = link
            .inertial
            .as_ref()
            .map(|i| (i, check::link(&i.mass, &i.inertia, check_inertia)));
        problems.into_iter().flat_map(move |(inertial, problems)| {
            problems.into_iter().map(move |p| {
                let at = match p.parameter {
                    check::LinkParameter::Mass => inertial.mass_at,
                    _ => inertial.inertia_at,
                };
                // A URDF link has no `check_inertia` of its own: the derive's covers them all.
                let message = p.message.replace(
                    "to this link",
                    "to the derive (`--no-check-inertia` to the command)",
                );
                error(at, format!("link `{}`: {message}", link.name))
            })
        })
    })
}

/// The model's joint for `segment`, with where its values are written.
fn joint(tree: &Tree, segment: Segment) -> Result<(Joint, JointPositions), Vec<FileError>> {
    let urdf = &tree.doc.joints[segment.joint];
    let (axis, friction) = (unit_axis(urdf), friction(urdf));
    let (axis, friction) = match (axis, friction) {
        (Ok(a), Ok(f)) => (a, f),
        (a, f) => {
            return Err(a
                .err()
                .into_iter()
                .chain(f.err().into_iter().flatten())
                .collect())
        }
    };
    let parts: Vec<Body> = segment
        .parts
        .iter()
        .map(|(link, pose)| Body::part(tree.doc.links[*link].inertial.as_ref(), pose))
        .collect();
    let body = Body::combine(&parts);
    let child = &tree.doc.links[tree.child(segment.joint)];
    let inertial = child.inertial.as_ref();
    let at: JointPositions = [
        ("type", urdf.at),
        ("axis", urdf.axis_at),
        ("mass", inertial.map_or(child.at, |i| i.mass_at)),
        ("inertia", inertial.map_or(child.at, |i| i.inertia_at)),
    ]
    .into_iter()
    .map(|(k, v)| (k.to_string(), v))
    .collect();
    let kind = if urdf.kind == Kind::Prismatic {
        JointKind::Prismatic
    } else {
        JointKind::Revolute
    };
    let link = Link {
        mass: body.mass,
        com: body.com,
        inertia: body.inertia,
        friction,
        ..Link::default()
    };
    let frame = AxisFrame {
        origin: segment.placement,
        axis,
    };
    let joint = Joint::framed(kind, frame, link);
    Ok((joint, at))
}

/// The joint's axis, a unit vector: a zero axis or one whose length is off 1 is an error.
fn unit_axis(joint: &UrdfJoint) -> Result<[Value; 3], FileError> {
    let squares = joint
        .axis
        .iter()
        .fold(Value::zero(), |acc, a| acc + a.clone() * a.clone());
    let length = squares.eval(&|_| None).unwrap_or_default().sqrt();
    let written = joint
        .axis
        .iter()
        .map(|a| a.eval(&|_| None).unwrap_or_default().to_string())
        .collect::<Vec<_>>()
        .join(" ");
    let name = &joint.name;
    if length == 0.0 {
        return Err(error(joint.axis_at, format!("joint `{name}`: the axis `{written}` is zero: give the direction the joint turns about or slides along, e.g. `0 0 1`")));
    }
    // One tolerance for every front end (the lowering's): URDF files write `0.7071068` for
    // 1/√2; such an axis is divided by its length, as Pinocchio does.
    if (length - 1.0).abs() > AXIS_LENGTH_TOLERANCE {
        return Err(error(joint.axis_at, format!("joint `{name}`: the axis `{written}` has length {length}, not 1: write a unit vector")));
    }
    if squares.exact().is_some_and(crate::symbolic::Number::is_one) {
        return Ok(joint.axis.clone());
    }
    Ok(std::array::from_fn(|i| {
        Value::from_f64(joint.axis[i].eval(&|_| None).unwrap_or_default() / length)
    }))
}

/// `<dynamics damping friction>` as viscous and Coulomb friction; none when both are zero or
/// absent. A negative coefficient is an error.
fn friction(joint: &UrdfJoint) -> Result<Option<Friction>, Vec<FileError>> {
    let mut errors = Vec::new();
    let mut coefficient = |entry: &Option<(Value, (usize, usize))>, key: &str| {
        let (value, at) = entry.clone().unwrap_or_default();
        if value
            .exact()
            .is_some_and(crate::symbolic::Number::is_negative)
        {
            errors.push(error(at, format!("joint `{}`: `<dynamics {key}=\"{}\">` is negative: a friction coefficient is 0 or more", joint.name, value.eval(&|_| None).unwrap_or_default())));
        }
        value
    };
    let viscous = coefficient(&joint.damping, "damping");
    let coulomb = coefficient(&joint.friction, "friction");
    if !errors.is_empty() {
        return Err(errors);
    }
    Ok(
        (!viscous.is_zero() || !coulomb.is_zero()).then(|| Friction {
            viscous,
            coulomb,
            offset: Value::zero(),
            smoothing: None,
        }),
    )
}
