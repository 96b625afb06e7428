//! The floating-base algorithms checked against values found another way: a single free body
//! from its momentum (no joints: `M` is its spatial inertia, `h` the gyroscopic and gravity
//! wrench), `M` by composite bodies against Newton-Euler's columns on hand-built trees, and
//! Solo 12 against Pinocchio's free flyer (`tests/data/floating/`).

use crate::unit::algo::tree_tests::{at, chain, robot, trees, R};
use dynamics_codegen::algo::{
    floating_crba, floating_gravity, floating_rnea, quaternion_rotation, Chain, FloatingBase,
    Inertial, Mat3, V3,
};
use dynamics_codegen::model::{Robot, Value};

/// A body of mass 2 with its centre of mass off the origin and a full inertia tensor.
fn lopsided() -> Inertial<f64> {
    Inertial {
        mass: 2.0,
        com: V3::new(0.1, -0.2, 0.3),
        inertia: [0.3, 0.25, 0.2, 0.01, -0.02, 0.015],
    }
}

fn identity() -> Mat3<f64> {
    Mat3::rot_z(0.0, 1.0)
}

/// A unit quaternion `[x, y, z, w]` from four numbers.
fn unit(q: [f64; 4]) -> [f64; 4] {
    let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    q.map(|x| x / norm)
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() < 1e-12 * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// One body, no joints: `M = [[m 1, −m[c]×], [m[c]×, I_O]]` with `I_O = I_c + m(|c|² 1 − c cᵀ)`,
/// and `h = [ω × p − m g_b, ω × L + v × p − c × m g_b]` from the momentum `p = m(v + ω × c)`
/// and the moment of momentum `L = I_O ω + m c × v` about the moving origin.
#[test]
fn a_single_free_body() {
    let link = lopsided();
    let base = FloatingBase::new(&link, identity(), V3::new(0.0, 0.0, 0.0));
    let empty = Chain { joints: Vec::new() };
    let (m, c) = (link.mass, link.com);
    let [ixx, iyy, izz, ixy, ixz, iyz] = link.inertia;
    let cc = c.dot(c);
    let io = [
        [
            ixx + m * (cc - c.x * c.x),
            ixy - m * c.x * c.y,
            ixz - m * c.x * c.z,
        ],
        [
            ixy - m * c.x * c.y,
            iyy + m * (cc - c.y * c.y),
            iyz - m * c.y * c.z,
        ],
        [
            ixz - m * c.x * c.z,
            iyz - m * c.y * c.z,
            izz + m * (cc - c.z * c.z),
        ],
    ];
    let mc = [
        [0.0, -m * c.z, m * c.y],
        [m * c.z, 0.0, -m * c.x],
        [-m * c.y, m * c.x, 0.0],
    ];
    let got = floating_crba(&empty, &base);
    for i in 0..3 {
        for j in 0..3 {
            close(got[i][j], if i == j { m } else { 0.0 }, "m 1");
            close(got[i][j + 3], -mc[i][j], "−m[c]×");
            close(got[i + 3][j], mc[i][j], "m[c]×");
            close(got[i + 3][j + 3], io[i][j], "I_O");
        }
    }
    let quaternion = unit([0.3, -0.5, 0.2, 0.8]);
    let gravity = V3::new(0.0, 0.0, -9.81);
    let g_b = quaternion_rotation(quaternion).tr_mul_vec(gravity);
    let (v, w) = (V3::new(0.4, -1.1, 0.7), V3::new(-0.9, 0.35, 1.6));
    let p = w.cross(c).add(v).scale(m);
    let l = V3::new(
        io[0][0] * w.x + io[0][1] * w.y + io[0][2] * w.z,
        io[1][0] * w.x + io[1][1] * w.y + io[1][2] * w.z,
        io[2][0] * w.x + io[2][1] * w.y + io[2][2] * w.z,
    )
    .add(c.cross(v).scale(m));
    let force = w.cross(p) - g_b.scale(m);
    let moment = w.cross(l).add(v.cross(p)) - c.cross(g_b).scale(m);
    let velocity = [v.x, v.y, v.z, w.x, w.y, w.z];
    let h = floating_rnea(&empty, &base, quaternion, &velocity, &[0.0; 6], gravity);
    for (k, e) in [force.x, force.y, force.z, moment.x, moment.y, moment.z]
        .into_iter()
        .enumerate()
    {
        close(h[k], e, "h");
    }
    let g = floating_gravity(&empty, &base, quaternion, gravity);
    let hold = [g_b.scale(-m), c.cross(g_b).scale(-m)];
    for (k, e) in [
        hold[0].x, hold[0].y, hold[0].z, hold[1].x, hold[1].y, hold[1].z,
    ]
    .into_iter()
    .enumerate()
    {
        close(g[k], e, "g");
    }
}

use std::ops::Add;

/// The quaternion's polynomial matrix is the rotation of Rodrigues' formula for a unit
/// quaternion: about the axis u by 2 acos w.
#[test]
fn quaternion_to_rotation() {
    let q = unit([0.3, -0.5, 0.2, 0.8]);
    let angle = 2.0 * q[3].acos();
    let s = (angle / 2.0).sin();
    let u = [q[0] / s, q[1] / s, q[2] / s];
    let (sa, ca) = angle.sin_cos();
    let r = quaternion_rotation(q);
    for i in 0..3 {
        for j in 0..3 {
            let delta = if i == j { 1.0 } else { 0.0 };
            let cross = match (i, j) {
                (0, 1) => -u[2],
                (1, 0) => u[2],
                (0, 2) => u[1],
                (2, 0) => -u[1],
                (1, 2) => -u[0],
                (2, 1) => u[0],
                _ => 0.0,
            };
            let e = ca * delta + sa * cross + (1.0 - ca) * u[i] * u[j];
            close(r.m[i][j], e, "R");
        }
    }
}

/// On hand-built trees with frame 0 turned and shifted on the base, column k of `M` by
/// composite bodies is Newton-Euler's `τ(a = e_k) − τ(a = 0)`, and `τ = M a + h`.
#[test]
fn composite_bodies_agree_with_newton_euler() {
    let (sr, cr) = (0.6f64.sin(), 0.6f64.cos());
    let rotation = Mat3::rot_x(sr, cr).mul(&Mat3::rot_z(0.4f64.sin(), 0.4f64.cos()));
    let base = FloatingBase::new(&lopsided(), rotation, V3::new(0.2, -0.1, 0.05));
    let quaternion = unit([-0.2, 0.7, 0.1, 0.4]);
    let gravity = V3::new(0.0, 0.0, -9.81);
    let mut specs = trees();
    specs.push(vec![at(None, R, 0.0, 0.0, 1.0)]);
    for spec in specs {
        let robot = robot(&spec, true);
        let n = robot.dof();
        let q: Vec<f64> = (0..n).map(|i| 0.3 + 0.7 * i as f64).collect();
        let c = chain(&robot, &q);
        let v: Vec<f64> = (0..n + 6).map(|i| (1.3 * i as f64).sin()).collect();
        let a: Vec<f64> = (0..n + 6).map(|i| (0.9 * i as f64).cos()).collect();
        let zeros = vec![0.0; n + 6];
        let m = floating_crba(&c, &base);
        let h = floating_rnea(&c, &base, quaternion, &v, &zeros, gravity);
        let tau = floating_rnea(&c, &base, quaternion, &v, &a, gravity);
        for k in 0..n + 6 {
            let mut e = zeros.clone();
            e[k] = 1.0;
            let column = floating_rnea(&c, &base, quaternion, &zeros, &e, V3::zero(0.0));
            let ma: f64 = (0..n + 6).map(|j| m[k][j] * a[j]).sum();
            close(tau[k], ma + h[k], "τ = M a + h");
            for (i, x) in column.iter().enumerate() {
                close(m[i][k], *x, "M column");
            }
        }
    }
}

/// The robot and floating body of `robots/urdf/floating/<name>.urdf`.
pub(crate) fn urdf_robot(name: &str) -> (Robot, dynamics_codegen::model::FreeFlyer) {
    let path = format!(
        "{}/../robots/urdf/floating/{name}.urdf",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the URDF");
    let chain = dynamics_codegen::front::Chain::default();
    let loaded = dynamics_codegen::front::load_urdf(&path, &text, chain, true).expect("loads");
    let flyer = dynamics_codegen::front::free_flyer(&text, None).expect("a floating body");
    (loaded.robot, flyer)
}

/// The numbers of a robot's floating base: its body and where frame 0 sits.
pub(crate) fn numeric_base(
    robot: &Robot,
    flyer: &dynamics_codegen::model::FreeFlyer,
) -> FloatingBase<f64> {
    let v = |x: &Value| x.eval(&|_| None).expect("a number");
    let b = &flyer.body;
    let link = Inertial {
        mass: v(&b.mass),
        com: V3::new(v(&b.com[0]), v(&b.com[1]), v(&b.com[2])),
        inertia: b.inertia.each_ref().map(v),
    };
    let r = &robot.base.rotation;
    let t = &robot.base.translation;
    let rotation = Mat3 {
        m: std::array::from_fn(|i| std::array::from_fn(|j| v(&r[i][j]))),
    };
    FloatingBase::new(&link, rotation, V3::new(v(&t[0]), v(&t[1]), v(&t[2])))
}

/// Solo 12 on its free flyer: `M`, `h`, `τ` and `g` against Pinocchio's `crba`,
/// `nonLinearEffects`, `rnea` and `computeGeneralizedGravity` at random states and unit
/// quaternions, to 1e-12 scaled by the largest entry.
#[test]
fn solo12_against_pinocchio() {
    let (robot, flyer) = urdf_robot("solo12");
    assert_eq!(flyer.link, "base_link");
    let base = numeric_base(&robot, &flyer);
    let path = format!(
        "{}/../tests/data/floating/solo12.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let data: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("the data")).expect("JSON");
    let list = |x: &serde_json::Value| -> Vec<f64> {
        x.as_array()
            .expect("a list")
            .iter()
            .map(|e| e.as_f64().expect("a number"))
            .collect()
    };
    let gravity = V3::new(0.0, 0.0, -9.81);
    let samples = data["samples"].as_array().expect("samples");
    assert!(samples.len() >= 10);
    for s in samples {
        let (q, v, a) = (list(&s["q"]), list(&s["v"]), list(&s["a"]));
        assert_eq!((q.len(), v.len()), (19, 18));
        let c = chain(&robot, &q[7..]);
        let quaternion = [q[3], q[4], q[5], q[6]];
        let zeros = vec![0.0; 18];
        let m: Vec<f64> = floating_crba(&c, &base).into_iter().flatten().collect();
        let expected_m: Vec<f64> = s["M"]
            .as_array()
            .expect("rows")
            .iter()
            .flat_map(list)
            .collect();
        for (what, got, expected) in [
            ("M", m, expected_m),
            (
                "h",
                floating_rnea(&c, &base, quaternion, &v, &zeros, gravity),
                list(&s["h"]),
            ),
            (
                "tau",
                floating_rnea(&c, &base, quaternion, &v, &a, gravity),
                list(&s["tau"]),
            ),
            (
                "g",
                floating_gravity(&c, &base, quaternion, gravity),
                list(&s["g"]),
            ),
        ] {
            let scale = expected.iter().fold(1.0f64, |x, e| x.max(e.abs()));
            for (k, (x, e)) in got.iter().zip(&expected).enumerate() {
                assert!((x - e).abs() <= 1e-12 * scale, "{what}[{k}]: {x} vs {e}");
            }
        }
    }
}
