#![allow(clippy::approx_constant)] // URDF files write 1.5708 and 3.14159: the inputs under test

use dynamics_codegen::model::Value;
use dynamics_codegen::model::{rotate_inertia, snap_angle, Placement, Pose};

fn num(v: &Value) -> f64 {
    v.eval(&|_| None).expect("a number")
}

/// `Rz(y) Ry(p) Rx(r)` written out, as URDF defines it.
fn rpy_matrix(r: f64, p: f64, y: f64) -> [[f64; 3]; 3] {
    let (sr, cr, sp, cp, sy, cy) = (r.sin(), r.cos(), p.sin(), p.cos(), y.sin(), y.cos());
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

fn placement(xyz: [f64; 3], rpy: [f64; 3]) -> Placement {
    Placement {
        xyz: xyz.map(Value::from_f64),
        rpy: rpy.map(Value::from_f64),
    }
}

#[test]
fn rpy_rotation_is_urdf_s() {
    for rpy in [
        [0.3, -1.1, 2.0],
        [1.5708, 0.0, -3.14159],
        [0.0486795, 1.2, 0.7],
    ] {
        let pose = placement([0.1, 0.2, 0.3], rpy).pose().unwrap();
        let expected = rpy_matrix(rpy[0], rpy[1], rpy[2]);
        for (row, want) in pose.rotation.iter().zip(expected) {
            for (v, w) in row.iter().zip(want) {
                assert!((num(v) - w).abs() < 2e-5, "{rpy:?}: {v} vs {w}");
            }
        }
    }
}

#[test]
fn near_quarter_turns_snap_exactly() {
    let pose = placement([0.0; 3], [1.5708, 3.14159, 1e-15])
        .pose()
        .unwrap();
    for row in &pose.rotation {
        for v in row {
            let x = v.exact().expect("exact").to_f64();
            assert!(x == 0.0 || x.abs() == 1.0, "{v}");
        }
    }
    assert_eq!(
        snap_angle(&Value::from_f64(0.0001)),
        Value::from_f64(0.0001)
    );
    // Beyond four turns, and where floats are coarser than the tolerance, kept as written.
    for far in [-1e308, 1e30, 17.0 * std::f64::consts::FRAC_PI_2] {
        assert_eq!(snap_angle(&Value::from_f64(far)), Value::from_f64(far));
    }
    assert_eq!(
        snap_angle(&Value::from_f64(-1.57079))
            .pi_multiple()
            .unwrap()
            .to_f64(),
        -0.5
    );
}

#[test]
fn a_pose_then_its_inverse_is_the_identity() {
    let pose = placement([0.4, -0.2, 1.1], [0.3, -1.1, 2.0])
        .pose()
        .unwrap();
    let round = pose.then(&pose.inverse());
    let id = Pose::identity();
    for i in 0..3 {
        assert!(num(&round.translation[i]).abs() < 1e-15);
        for j in 0..3 {
            assert!((num(&round.rotation[i][j]) - num(&id.rotation[i][j])).abs() < 1e-15);
        }
    }
}

#[test]
fn rotating_an_inertia_keeps_its_trace_and_turns_its_axes() {
    let quarter = placement([0.0; 3], [0.0, 0.0, std::f64::consts::FRAC_PI_2])
        .pose()
        .unwrap();
    let inertia = [1.0, 2.0, 3.0, 0.1, 0.0, 0.0].map(Value::from_f64);
    let turned = rotate_inertia(&quarter.rotation, &inertia).map(|v| num(&v));
    // A quarter turn about z swaps x and y: Ixx ↔ Iyy, Ixy → −Ixy.
    assert_eq!(turned, [2.0, 1.0, 3.0, -0.1, 0.0, 0.0]);
}
