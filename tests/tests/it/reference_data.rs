//! The generated code against the reference data of `data/reference/` (Pinocchio 4.1.0,
//! cross-checked with the Robotics Toolbox) and of `data/panda/` (a 7-joint arm, Pinocchio
//! 4.1.0, checked against the URDF its parameters come from) and of `data/frames/` (joints given
//! by placements and axes, Pinocchio 4.1.0 models built from them): for every sample, τ, M, C,
//! C·qd + g, g and both energies match to 1e-10, scaled as max|a − b| / max(1, max|b|).

use dynamics_runtime::Dynamics;
use dynamics_tests::reference::{self, Friction};
use dynamics_tests::robots::{
    General, NikuPolar, NikuTwoLink, Panda, Puma560, Random1, Random2, Random5, Stanford, Tilted,
    Ur5, Ur5Urdf,
};

fn check<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) -> f64 {
    reference::check(robot, file, Friction::None)
}

#[test]
fn puma560() {
    check(&Puma560, "reference/data/puma560.json");
}

#[test]
fn stanford() {
    check(&Stanford, "reference/data/stanford.json");
}

#[test]
fn ur5() {
    check(&Ur5, "reference/data/ur5.json");
}

#[test]
fn niku_2link() {
    check(&NikuTwoLink, "reference/data/niku_2link.json");
}

#[test]
fn niku_polar() {
    check(&NikuPolar, "reference/data/niku_polar.json");
}

#[test]
fn random1() {
    check(&Random1, "reference/data/random1.json");
}

#[test]
fn random5() {
    check(&Random5, "reference/data/random5.json");
}

/// Franka Emika Panda: 7 joints, the modified (Craig) convention, inertias from its URDF.
#[test]
fn panda_seven_joints() {
    check(&Panda, "panda/data.json");
}

/// random2 uses the modified (Craig) convention.
#[test]
fn random2_modified_convention() {
    check(&Random2, "reference/data/random2.json");
}

/// UR5's joints as its URDF places them, quarter turns written 1.5708 and 3.14159.
#[test]
fn ur5_urdf_style_frames() {
    check(&Ur5Urdf, "frames/ur5_urdf.json");
}

/// Quarter turns written as floats, a prismatic joint along −y, gravity off the axes.
#[test]
fn tilted_frames() {
    check(&Tilted, "frames/tilted.json");
}

/// The tilted robot of `data/frames/tilted.toml` written in the attribute instead, with the
/// angles in degrees and a struct field for a length.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -6, -7.5],
    joints = [
        revolute(xyz = [0.1, 0, 0.2], rpy = [180 deg, 0, 0], axis = [1, 0, 0]),
        prismatic(xyz = [0, l2, 0], rpy = [0, -90 deg, 0], axis = [0, -1, 0]),
        revolute(xyz = [0.05, 0, -0.15], rpy = [0, 0, 90 deg]),
    ],
    link(mass = 1.5, com = [0.05, 0.01, -0.02], inertia = [0.02, 0.03, 0.025, 0.001, 0, -0.002]),
    link(mass = 0.8, com = [0, -0.1, 0.03], inertia = [0.01, 0.004, 0.011, 0, 0.0005, 0]),
    link(mass = 0.6, com = [0.02, 0, 0.01], inertia = [0.003, 0.004, 0.005, 0, 0, 0.0002]),
)]
struct TiltedInTheAttribute {
    l2: f64,
}

#[test]
fn tilted_frames_in_the_attribute() {
    check(&TiltedInTheAttribute { l2: 0.3 }, "frames/tilted.json");
}

/// Generic placements and axes, prismatic joints.
#[test]
fn general_frames() {
    check(&General, "frames/general.json");
}
