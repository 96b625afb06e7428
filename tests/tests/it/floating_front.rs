//! `base = floating` beside the front ends other than a URDF: Solo 12 from a description file
//! (`robots/floating/solo12.toml`, written from its URDF by `robots/floating/from_urdf.py`)
//! against Pinocchio 4.1 (`tests/data/floating/solo12.json`), and a two-legged toy given as a
//! URDF, a `joints = [..]` list and a Khalil-Kleinfinger D-H table, the floating body in the
//! attribute's `base = floating(mass = .., com = [..], inertia = [..])`: the same M, h, τ, g;
//! and the toy with no joint's axis along its frame's z, as a URDF and a joint list.

use super::floating_base::{check_against_pinocchio, reference, Solo12};
use dynamics_reference::scaled_error;
use dynamics_runtime::FloatingDynamics;

/// Solo 12 from its description file, the `[floating]` table its base link.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(file = "../robots/floating/solo12.toml", base = floating)]
struct Solo12File;

#[test]
fn solo12_from_a_description_file_against_pinocchio() {
    assert_eq!((Solo12File::NQ, Solo12File::NV), (19, 18));
    check_against_pinocchio(&Solo12File, "solo12");
    // And the URDF's robot, to rounding (the file's bodies are combined in Python).
    for s in reference("solo12")["samples"].as_array().expect("samples") {
        let q = super::floating_base::array::<19>(&s["q"]);
        let (a, b) = (Solo12File.mass_matrix(&q), Solo12.mass_matrix(&q));
        let flat = |m: [[f64; 18]; 18]| m.iter().flatten().copied().collect::<Vec<_>>();
        assert!(scaled_error(&flat(a), &flat(b)) < 1e-14);
    }
}

/// The toy from its URDF.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(urdf = "data/floating/two_legs.urdf", base = floating)]
struct TwoLegsUrdf;

/// The same toy as a list of joints given by frames, the trunk in the attribute.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    base = floating(mass = 2, com = [0.01, 0.02, -0.03], inertia = [0.02, 0.03, 0.04, 0.001, 0, 0.002]),
    gravity = [0, 0, -9.81],
    joints = [
        revolute(xyz = [0.1, 0, 0], axis = [0, 0, 1], parent = 0),
        revolute(xyz = [0.2, 0, 0], rpy = [90 deg, 0, 0], axis = [0, 0, 1]),
        revolute(xyz = [-0.1, 0, 0], axis = [0, 0, 1], parent = 0),
        revolute(xyz = [-0.2, 0, 0], rpy = [90 deg, 0, 0], axis = [0, 0, 1]),
    ],
    link(mass = 0.5, com = [0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
    link(mass = 0.5, com = [-0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [-0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
)]
struct TwoLegsJoints;

/// The same toy as a Khalil-Kleinfinger table, `[θ, d, a, α, antecedent, γ, b]`: each frame
/// `Rx(α) Tx(a) Rz(θ) Tz(d)` on its antecedent's, as the joints' `origin` and `axis` above.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    base = floating(mass = 2, com = [0.01, 0.02, -0.03], inertia = [0.02, 0.03, 0.04, 0.001, 0, 0.002]),
    gravity = [0, 0, -9.81],
    convention = modified,
    dh = [
        [q, 0, 0.1, 0, 0, 0, 0],
        [q, 0, 0.2, 90 deg, 1, 0, 0],
        [q, 0, -0.1, 0, 0, 0, 0],
        [q, 0, -0.2, 90 deg, 3, 0, 0],
    ],
    link(mass = 0.5, com = [0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
    link(mass = 0.5, com = [-0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [-0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
)]
struct TwoLegsDh;

/// The toy with its hips turning about x and its knees about y, the hips' frames turned: no
/// joint's axis is its frame's z, so the joint list's lowering puts a fixed frame before each
/// leg's first D-H frame, on the floating body.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(urdf = "data/floating/two_legs_tilted.urdf", base = floating)]
struct TiltedUrdf;

/// The tilted toy as a list of joints.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    base = floating(mass = 2, com = [0.01, 0.02, -0.03], inertia = [0.02, 0.03, 0.04, 0.001, 0, 0.002]),
    gravity = [0, 0, -9.81],
    joints = [
        revolute(xyz = [0.1, 0.05, -0.02], rpy = [0.3 rad, 0, 0.2 rad], axis = [1, 0, 0], parent = 0),
        revolute(xyz = [0, 0, -0.2], axis = [0, 1, 0]),
        revolute(xyz = [-0.1, 0.05, -0.02], rpy = [0, -0.4 rad, 0], axis = [1, 0, 0], parent = 0),
        revolute(xyz = [0, 0, -0.2], axis = [0, 1, 0]),
    ],
    link(mass = 0.5, com = [0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
    link(mass = 0.5, com = [-0.05, 0.01, 0], inertia = [0.001, 0.002, 0.003, 0.0001, 0, 0]),
    link(mass = 0.3, com = [-0.1, 0, 0.01], inertia = [0.0005, 0.001, 0.0012, 0, 0.0001, 0]),
)]
struct TiltedJoints;

/// A state of the toy from `seed`: a unit quaternion, angles and rates in ±1.5 (a fixed
/// linear congruential sequence, so that the test reads the same numbers every run).
fn state(seed: u64) -> ([f64; 11], [f64; 10], [f64; 10]) {
    let mut x = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
    let mut next = || {
        x = x
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (x >> 11) as f64 / (1u64 << 53) as f64 * 3.0 - 1.5
    };
    let mut q: [f64; 11] = std::array::from_fn(|_| next());
    let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
    q[3..7].iter_mut().for_each(|x| *x /= norm);
    (
        q,
        std::array::from_fn(|_| next()),
        std::array::from_fn(|_| next()),
    )
}

/// M, h, τ, g of `robot` at `(q, v, a)`, in one list.
fn outputs<R: FloatingDynamics<11, 10>>(
    robot: &R,
    (q, v, a): &([f64; 11], [f64; 10], [f64; 10]),
) -> Vec<f64> {
    let mut out: Vec<f64> = robot.mass_matrix(q).iter().flatten().copied().collect();
    out.extend(robot.bias_forces(q, v));
    out.extend(robot.inverse_dynamics(q, v, a));
    out.extend(robot.generalized_gravity(q));
    out
}

#[test]
fn a_joint_list_and_a_dh_table_on_a_floating_base_are_their_urdf() {
    for seed in 0..8 {
        let x = state(seed);
        let urdf = outputs(&TwoLegsUrdf, &x);
        // Not a robot whose legs do not move the base: the coupling is there.
        let m = TwoLegsUrdf.mass_matrix(&x.0);
        assert!((0..6).map(|i| m[i][6].abs()).sum::<f64>() > 1e-3);
        for (what, got) in [
            ("joints", outputs(&TwoLegsJoints, &x)),
            ("dh", outputs(&TwoLegsDh, &x)),
        ] {
            let error = scaled_error(&got, &urdf);
            assert!(error < 1e-13, "seed {seed}: {what} off by {error:e}");
        }
    }
}

#[test]
fn a_joint_list_whose_axes_are_not_z_on_a_floating_base_is_its_urdf() {
    for seed in 0..8 {
        let x = state(seed);
        let (urdf, joints) = (outputs(&TiltedUrdf, &x), outputs(&TiltedJoints, &x));
        let error = scaled_error(&joints, &urdf);
        assert!(error < 1e-13, "seed {seed}: off by {error:e}");
        // Not the untilted toy: the axes matter.
        assert!(scaled_error(&urdf, &outputs(&TwoLegsUrdf, &x)) > 1e-3);
    }
}
