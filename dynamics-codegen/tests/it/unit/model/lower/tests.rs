//! The lowering against an independent plain product: on random robots given URDF style, the
//! pose of every user link frame, `P_1 M_1(q_1) ⋯ P_i M_i(q_i)` with 4×4 `f64` matrices
//! (Rodrigues for a revolute joint's motion), equals `base · A_1(q_1) ⋯ A_i(q_i) · link_pose_i`
//! from the derived modified D-H table, and every link's mass, com and inertia in base
//! coordinates agree.

use dynamics_codegen::model::lower_frames;
use dynamics_codegen::model::{
    AxisFrame, Convention, Joint, JointKind, Link, Placement, Pose, Robot, Value,
};
use dynamics_codegen::symbolic::Number;
use dynamics_test_support::Rng;

pub(super) type M4 = [[f64; 4]; 4];

pub(super) fn num(v: &Value) -> f64 {
    v.eval(&|_| None).expect("a number")
}

pub(super) fn mul(a: &M4, b: &M4) -> M4 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

pub(super) fn identity() -> M4 {
    std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j))))
}

pub(super) fn rotation(r: [[f64; 3]; 3], t: [f64; 3]) -> M4 {
    let mut m = identity();
    for i in 0..3 {
        m[i][..3].copy_from_slice(&r[i]);
        m[i][3] = t[i];
    }
    m
}

/// Rotation by `angle` about the unit `axis` (Rodrigues).
pub(super) fn rodrigues(axis: [f64; 3], angle: f64) -> [[f64; 3]; 3] {
    let (s, c) = angle.sin_cos();
    let [x, y, z] = axis;
    let v = 1.0 - c;
    [
        [c + x * x * v, x * y * v - z * s, x * z * v + y * s],
        [y * x * v + z * s, c + y * y * v, y * z * v - x * s],
        [z * x * v - y * s, z * y * v + x * s, c + z * z * v],
    ]
}

/// `Trans(xyz) · Rz(yaw) Ry(pitch) Rx(roll)`, each factor by Rodrigues.
pub(super) fn placement(xyz: [f64; 3], rpy: [f64; 3]) -> M4 {
    let r = |k: usize| {
        rotation(
            rodrigues(std::array::from_fn(|i| f64::from(u8::from(i == k))), rpy[k]),
            [0.0; 3],
        )
    };
    mul(
        &rotation(rodrigues([0.0, 0.0, 1.0], 0.0), xyz),
        &mul(&r(2), &mul(&r(1), &r(0))),
    )
}

pub(super) fn pose_matrix(p: &Pose) -> M4 {
    rotation(
        p.rotation.clone().map(|row| row.map(|v| num(&v))),
        p.translation.clone().map(|v| num(&v)),
    )
}

/// Modified D-H: `Rotx(α) Transx(a) Rotz(θ) Transz(d)`.
pub(super) fn modified_dh(alpha: f64, a: f64, theta: f64, d: f64) -> M4 {
    let (sa, ca) = alpha.sin_cos();
    let (st, ct) = theta.sin_cos();
    [
        [ct, -st, 0.0, a],
        [st * ca, ct * ca, -sa, -sa * d],
        [st * sa, ct * sa, ca, ca * d],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// A random angle: a quarter turn (exact, as `k/2 · π`) or a generic angle.
fn random_angle(rng: &mut Rng) -> Value {
    if rng.below(3) == 0 {
        Value::from_f64(rng.range(-3.0, 3.0))
    } else {
        let k = i128::try_from(rng.below(8)).unwrap() - 3;
        Value::num(Number::ratio(k, 2).unwrap()) * Value::Pi
    }
}

/// A random unit axis: along a coordinate axis, a rational unit vector, or generic.
fn random_axis(rng: &mut Rng) -> [Value; 3] {
    let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
    let k = rng.below(3);
    let mut axis = [0.0; 3];
    match rng.below(4) {
        0 => {
            axis[k] = 0.6 * sign;
            axis[(k + 1) % 3] = 0.8;
        }
        1 => {
            let v = rng.vector(3, -1.0, 1.0);
            let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            axis = std::array::from_fn(|i| v[i] / n);
        }
        _ => axis[k] = sign,
    }
    axis.map(Value::from_f64)
}

fn random_length(rng: &mut Rng) -> Value {
    if rng.below(3) == 0 {
        Value::zero()
    } else {
        Value::from_f64((rng.range(-0.5, 0.5) * 1000.0).round() / 1000.0)
    }
}

pub(super) fn random_joint(rng: &mut Rng) -> Joint {
    let diagonal = rng.vector(3, 0.5, 1.0);
    let off = rng.vector(3, -0.1, 0.1);
    Joint {
        kind: if rng.below(4) == 0 {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        },
        theta: Value::zero(),
        d: Value::zero(),
        a: Value::zero(),
        alpha: Value::zero(),
        link: Link {
            mass: Value::from_f64(rng.range(0.5, 3.0)),
            com: std::array::from_fn(|_| random_length(rng)),
            inertia: [
                diagonal[0],
                diagonal[1],
                diagonal[2],
                off[0],
                off[1],
                off[2],
            ]
            .map(Value::from_f64),
            ..Link::default()
        },
        frame: Some(AxisFrame {
            origin: Placement {
                xyz: std::array::from_fn(|_| random_length(rng)),
                rpy: std::array::from_fn(|_| random_angle(rng)),
            },
            axis: random_axis(rng),
        }),
        link_pose: Pose::identity(),
        branch: None,
        mimic: None,
    }
}

pub(super) fn random_robot(rng: &mut Rng) -> Robot {
    Robot {
        name: "random".into(),
        convention: Convention::Standard,
        gravity: [0.3, -1.2, -9.81].map(Value::from_f64),
        joints: (0..=rng.below(7)).map(|_| random_joint(rng)).collect(),
        base: Pose::identity(),
        tool: None,
        tips: Vec::new(),
    }
}

/// The user's link frames at `q`, by the plain product.
pub(super) fn user_frames(robot: &Robot, q: &[f64]) -> Vec<M4> {
    let mut pose = identity();
    robot
        .joints
        .iter()
        .zip(q)
        .map(|(joint, &qi)| {
            let frame = joint.frame.as_ref().unwrap();
            let axis = frame.axis.clone().map(|v| num(&v));
            let o = &frame.origin;
            pose = mul(
                &pose,
                &placement(
                    o.xyz.clone().map(|v| num(&v)),
                    o.rpy.clone().map(|v| num(&v)),
                ),
            );
            let motion = match joint.kind {
                JointKind::Revolute => rotation(rodrigues(axis, qi), [0.0; 3]),
                JointKind::Prismatic => rotation(rodrigues(axis, 0.0), axis.map(|x| x * qi)),
            };
            pose = mul(&pose, &motion);
            pose
        })
        .collect()
}

/// D-H frames at `q`, from the lowered table.
pub(super) fn dh_frames(robot: &Robot, q: &[f64]) -> Vec<M4> {
    assert_eq!(robot.convention, Convention::Modified);
    let mut pose = pose_matrix(&robot.base);
    robot
        .joints
        .iter()
        .zip(q)
        .map(|(j, &qi)| {
            let (theta, d) = match j.kind {
                JointKind::Revolute => (num(&j.theta) + qi, num(&j.d)),
                JointKind::Prismatic => (num(&j.theta), num(&j.d) + qi),
            };
            pose = mul(&pose, &modified_dh(num(&j.alpha), num(&j.a), theta, d));
            pose
        })
        .collect()
}

pub(super) fn close(a: &M4, b: &M4, what: &str) {
    for i in 0..4 {
        for j in 0..4 {
            assert!((a[i][j] - b[i][j]).abs() < 1e-9, "{what}: {a:?} vs {b:?}");
        }
    }
}

/// Inertia `R I Rᵀ` and com `R c + t` in base coordinates.
fn in_base(frame: &M4, com: &[Value; 3], inertia: &[Value; 6]) -> ([f64; 3], [[f64; 3]; 3]) {
    let c = com.clone().map(|v| num(&v));
    let [xx, yy, zz, xy, xz, yz] = inertia.clone().map(|v| num(&v));
    let tensor = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
    let r = |i: usize, j: usize| frame[i][j];
    let com = std::array::from_fn(|i| (0..3).map(|k| r(i, k) * c[k]).sum::<f64>() + frame[i][3]);
    let inertia = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3)
                .flat_map(|k| (0..3).map(move |l| (k, l)))
                .map(|(k, l)| r(i, k) * tensor[k][l] * r(j, l))
                .sum()
        })
    });
    (com, inertia)
}

#[test]
fn random_frames_lower_to_the_same_kinematics_and_inertias() {
    let mut rng = Rng::new(16);
    for case in 0..300 {
        let user = random_robot(&mut rng);
        let mut lowered = user.clone();
        lower_frames(&mut lowered).unwrap_or_else(|p| panic!("case {case}: {p:?}"));
        // D-H frame 0 at the base origin: potential energies agree.
        assert!(lowered.base.translation.iter().all(Value::is_zero));
        let base = pose_matrix(&lowered.base);
        let gravity = lowered.gravity.clone().map(|v| num(&v));
        for (k, want) in [0.3, -1.2, -9.81].into_iter().enumerate() {
            let got: f64 = (0..3).map(|l| base[k][l] * gravity[l]).sum();
            assert!((got - want).abs() < 1e-9, "case {case}: gravity");
        }
        for _ in 0..3 {
            let q = rng.vector(user.dof(), -3.0, 3.0);
            let (want, dh) = (user_frames(&user, &q), dh_frames(&lowered, &q));
            for (i, (w, d)) in want.iter().zip(&dh).enumerate() {
                let got = mul(d, &pose_matrix(&lowered.joints[i].link_pose));
                close(&got, w, &format!("case {case}, link {}", i + 1));
                let (uj, lj) = (&user.joints[i], &lowered.joints[i]);
                assert_eq!(uj.link.mass, lj.link.mass);
                let (c0, i0) = in_base(w, &uj.link.com, &uj.link.inertia);
                let (c1, i1) = in_base(d, &lj.link.com, &lj.link.inertia);
                for k in 0..3 {
                    assert!((c0[k] - c1[k]).abs() < 1e-9, "case {case} com");
                    for l in 0..3 {
                        assert!((i0[k][l] - i1[k][l]).abs() < 1e-9, "case {case} inertia");
                    }
                }
            }
        }
    }
}

/// UR5's six joints as its URDF writes them (example-robot-data 6.0.0, `robots/urdf/ur5.urdf`).
fn ur5() -> Robot {
    #[allow(clippy::approx_constant)] // as the URDF writes it: the input under test
    let quarter = 1.570_796_326_79;
    let joints = [
        ([0.0, 0.0, 0.089159], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.13585, 0.0], [0.0, quarter, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, -0.1197, 0.425], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, 0.39225], [0.0, quarter, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.093, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 0.09465], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    ];
    let mut rng = Rng::new(5);
    Robot {
        name: "ur5".into(),
        convention: Convention::Standard,
        gravity: [0.0, 0.0, -9.81].map(Value::from_f64),
        joints: joints
            .into_iter()
            .map(|(xyz, rpy, axis)| Joint {
                kind: JointKind::Revolute,
                frame: Some(AxisFrame {
                    origin: Placement {
                        xyz: xyz.map(Value::from_f64),
                        rpy: rpy.map(Value::from_f64),
                    },
                    axis: axis.map(Value::from_f64),
                }),
                ..random_joint(&mut rng)
            })
            .collect(),
        base: Pose::identity(),
        tool: None,
        tips: Vec::new(),
    }
}

#[test]
fn ur5_lowers_to_an_exact_table_with_its_parallel_offsets_in_d4() {
    let mut robot = ur5();
    lower_frames(&mut robot).unwrap();
    let column = |f: fn(&Joint) -> &Value| -> Vec<String> {
        robot.joints.iter().map(|j| f(j).to_string()).collect()
    };
    let half = "-1/2 * pi";
    assert_eq!(
        column(|j| &j.alpha),
        ["0", half, "0", "0", half, "1/2 * pi"]
    );
    // Hand derivation: a2, a3 are the upper arm and forearm; 0.13585 − 0.1197 + 0.093 = 0.10915.
    assert_eq!(column(|j| &j.a), ["0", "0", "17/40", "1569/4000", "0", "0"]);
    assert_eq!(column(|j| &j.theta), ["0"; 6]);
    assert_eq!(
        column(|j| &j.d),
        ["89159/1000000", "0", "0", "2183/20000", "1893/20000", "0"]
    );
    let all_exact = robot.joints.iter().all(|j| {
        [&j.alpha, &j.a, &j.theta, &j.d]
            .into_iter()
            .all(|v| v.pi_multiple().is_some() || v.exact().is_some_and(Number::is_exact))
    });
    assert!(all_exact);
    // D-H frame 0 is the base frame.
    assert_eq!(robot.base, Pose::identity());
}
