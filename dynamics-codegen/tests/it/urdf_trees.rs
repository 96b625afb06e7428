//! URDF trees through the front door (`pipeline::load`), at the model level: the Allegro hand
//! and Baxter of `robots/urdf/trees/` against Pinocchio 4.1.0's data (`tests/data/trees/`,
//! written in the front end's joint order): the joints' kinds, antecedents, limits and damping,
//! each link's mass, and every tip frame's pose at the samples' q, composed from the lowered
//! Khalil-Kleinfinger table (`Rotz(γ) Transz(b) Rotx(α) Transx(a) Rotz(θ) Transz(d)` along the
//! antecedents, then the link's pose) and Pinocchio's placement of the frame on its joint.

use dynamics_codegen::model::{JointKind, Robot, Value};
use dynamics_codegen::pipeline::{self, Source};
use dynamics_codegen::Chain;
use serde_json::Value as Json;

type M4 = [[f64; 4]; 4];

fn num(v: &Value) -> f64 {
    v.eval(&|_| None).expect("a number")
}

fn mul(a: &M4, b: &M4) -> M4 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

fn matrix(rotation: impl Fn(usize, usize) -> f64, translation: impl Fn(usize) -> f64) -> M4 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i, j) {
            (3, 3) => 1.0,
            (3, _) => 0.0,
            (_, 3) => translation(i),
            _ => rotation(i, j),
        })
    })
}

fn rot_z(angle: f64, along: f64) -> M4 {
    let (s, c) = angle.sin_cos();
    [
        [c, -s, 0.0, 0.0],
        [s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, along],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

fn rot_x(angle: f64, along: f64) -> M4 {
    let (s, c) = angle.sin_cos();
    [
        [1.0, 0.0, 0.0, along],
        [0.0, c, -s, 0.0],
        [0.0, s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

fn pose(p: &dynamics_codegen::model::Pose) -> M4 {
    matrix(|i, j| num(&p.rotation[i][j]), |i| num(&p.translation[i]))
}

/// Each joint's link frame (the user's, as the URDF's child link) in the base frame at `q`.
fn link_frames(robot: &Robot, q: &[f64]) -> Vec<M4> {
    let mut frames: Vec<M4> = Vec::new();
    let base = pose(&robot.base);
    for (i, j) in robot.joints.iter().enumerate() {
        let (theta, d) = match j.kind {
            JointKind::Revolute => (num(&j.theta) + q[i], num(&j.d)),
            JointKind::Prismatic => (num(&j.theta), num(&j.d) + q[i]),
        };
        let (gamma, b) = j
            .branch
            .as_ref()
            .map_or((0.0, 0.0), |br| (num(&br.gamma), num(&br.b)));
        let parent = robot.parent(i).map_or(base, |p| frames[p]);
        let step = mul(&rot_z(gamma, b), &rot_x(num(&j.alpha), 0.0));
        let step = mul(&step, &mul(&rot_x(0.0, num(&j.a)), &rot_z(theta, d)));
        frames.push(mul(&parent, &step));
    }
    // The D-H frames carried to the user's link frames.
    let user = robot.joints.iter().map(|j| pose(&j.link_pose));
    frames.iter().zip(user).map(|(f, u)| mul(f, &u)).collect()
}

fn data(name: &str) -> Json {
    let path = format!("../tests/data/trees/{name}.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn source<'a>(path: &'a str, tips: &'a [&'a str]) -> Source<'a> {
    Source {
        chain: Chain {
            tips,
            ..Chain::default()
        },
        // The Allegro hand's published inertias break the triangle inequality (as in the data).
        check_inertia: false,
        ..Source::file(path)
    }
}

fn load(urdf: &str, tips: &[&str]) -> Result<pipeline::Loaded, Vec<pipeline::Diagnostic>> {
    let path = format!("../robots/urdf/trees/{urdf}.urdf");
    pipeline::load(&source(&path, tips))
}

fn floats(v: &Json) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// The robot's joints keep the data's joints `keep` (indices into its lists), in order.
fn check_joints(robot: &Robot, data: &Json, keep: &[usize], source: &Source) {
    let index = |i: usize| keep.iter().position(|&k| k == i);
    let parents: Vec<Option<usize>> = keep
        .iter()
        .map(|&k| data["parents"][k].as_u64().and_then(|p| index(p as usize)))
        .collect();
    let got: Vec<Option<usize>> = (0..robot.dof()).map(|i| robot.parent(i)).collect();
    assert_eq!(got, parents);
    for (i, &k) in keep.iter().enumerate() {
        let joint = &robot.joints[i];
        let kind = match data["joint_types"][k].as_str().unwrap() {
            "prismatic" => JointKind::Prismatic,
            _ => JointKind::Revolute,
        };
        assert_eq!(joint.kind, kind, "joint {i}");
        let damping = joint
            .link
            .friction
            .as_ref()
            .map_or(0.0, |f| num(&f.viscous));
        assert_eq!(damping, data["damping"][k].as_f64().unwrap(), "joint {i}");
        let mass = data["pinocchio_model"]["joints"][k]["mass"]
            .as_f64()
            .unwrap();
        assert!(
            (num(&joint.link.mass) - mass).abs() <= 1e-12 * mass.max(1.0),
            "joint {i}"
        );
    }
    let limits = pipeline::joint_limits(source).unwrap();
    let bounds: Vec<[Option<f64>; 2]> = limits.iter().map(|l| [l.lower, l.upper]).collect();
    let want: Vec<[Option<f64>; 2]> = keep
        .iter()
        .map(|&k| std::array::from_fn(|e| data["limits"][k][e].as_f64()))
        .collect();
    assert_eq!(bounds, want);
}

/// Every Pinocchio frame on a kept joint, at every sample: its pose from the robot's table.
fn check_tip_poses(robot: &Robot, data: &Json, keep: &[usize]) -> usize {
    let mut checked = 0;
    for sample in data["samples"].as_array().unwrap() {
        let q_all = floats(&sample["q"]);
        let q: Vec<f64> = keep.iter().map(|&k| q_all[k]).collect();
        let frames = link_frames(robot, &q);
        for frame in data["pinocchio_model"]["frames"].as_array().unwrap() {
            let joint = frame["parent"].as_u64().unwrap() as usize - 1;
            let Some(i) = keep.iter().position(|&k| k == joint) else {
                continue;
            };
            let Some(want) = sample["tips"].get(frame["name"].as_str().unwrap()) else {
                continue;
            };
            let r = |a: usize, b: usize| frame["rotation"][a][b].as_f64().unwrap();
            let on_joint = matrix(r, |a| frame["translation"][a].as_f64().unwrap());
            let got = mul(&frames[i], &on_joint);
            for (a, row) in got.iter().enumerate() {
                for (b, x) in row.iter().enumerate() {
                    let w = want["pose"][a][b].as_f64().unwrap();
                    assert!((x - w).abs() < 1e-9, "{}: {got:?} vs {want}", frame["name"]);
                }
            }
            checked += 1;
        }
    }
    checked
}

#[test]
fn the_allegro_hand_comes_in_as_its_tree() {
    let data = data("allegro_right_hand");
    let robot = load("allegro_right_hand", &[]).expect("loads").robot;
    assert_eq!(robot.dof(), 16);
    assert!(robot.is_tree());
    let all: Vec<usize> = (0..16).collect();
    let path = "../robots/urdf/trees/allegro_right_hand.urdf";
    check_joints(&robot, &data, &all, &source(path, &[]));
    // Four fingertips at twenty samples.
    assert_eq!(check_tip_poses(&robot, &data, &all), 80);
}

#[test]
fn baxter_comes_in_with_its_mimic_fingers_and_without_them() {
    // Each gripper's right finger follows its left one, as the data's `mimic` says: 19 joints,
    // 17 coordinates.
    let whole = load("baxter", &[]).expect("loads").robot;
    assert_eq!((whole.dof(), whole.coordinates().len()), (19, 17));
    let mimics: Vec<(usize, usize, Option<f64>, Option<f64>)> = (0..19)
        .filter_map(|i| {
            let m = whole.joints[i].mimic.as_ref()?;
            let number = |v: &Value| v.eval(&|_| None);
            Some((i, m.joint, number(&m.multiplier), number(&m.offset)))
        })
        .collect();
    assert_eq!(
        mimics,
        [
            (9, 8, Some(-1.0), Some(0.0)),
            (18, 17, Some(-1.0), Some(0.0))
        ]
    );
    // The head and both arms, to the grippers' end-point frames above the fingers.
    let data = data("baxter_no_mimic");
    let tips = ["head", "right_gripper", "left_gripper"];
    let robot = load("baxter", &tips).expect("loads").robot;
    let keep: Vec<usize> = (0..19).filter(|&k| ![8, 9, 17, 18].contains(&k)).collect();
    check_joints(
        &robot,
        &data,
        &keep,
        &source("../robots/urdf/trees/baxter.urdf", &tips),
    );
    // The head and the two grippers' frames at twenty samples.
    assert_eq!(check_tip_poses(&robot, &data, &keep), 60);
}

/// A fixed-base tree's fetch-bound ∂q̈ in lanes is one function per subtree hanging from the
/// base (their blocks of M are their own): Baxter's head and two arms. The Allegro hand's
/// (four fingers, not fetch-bound: apart they measured no faster) and the Panda with free
/// fingers' (whose fingers share the arm's joints) keep one function.
#[test]
fn a_trees_forward_derivatives_by_subtree() {
    use dynamics_codegen::{Family, FamilySet};
    let families = FamilySet::default().with(Family::Derivatives);
    let functions = |urdf: &str, tips: &[&str]| {
        let loaded = load(urdf, tips).expect("loads");
        let items = loaded.rust_module(families, None).expect("a module").items;
        let items = items.to_string();
        (1..=5)
            .take_while(|k| items.contains(&format!("fn forward_dynamics_derivatives_rows{k}")))
            .count()
    };
    assert_eq!(functions("allegro_right_hand", &[]), 0);
    let tips = ["head", "right_gripper", "left_gripper"];
    assert_eq!(functions("baxter", &tips), 3);
    assert_eq!(functions("panda_free_fingers", &[]), 0);
}
