//! Each joint's limits: from the options, the URDF or the defaults; a mimic joint's.

use dynamics_codegen::model::Robot;
use dynamics_codegen::pipeline::Limit;
use dynamics_identification::excite::limits::{joint_limits, Origin};
use dynamics_identification::Error;

/// A revolute and a prismatic joint.
fn robot() -> Robot {
    let text =
        "name = \"rp\"\ngravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
                [[joints]]\ntype = \"prismatic\"\nmass = 1\n";
    let source = dynamics_codegen::Source {
        path: "rp.toml",
        text: Some(text),
        ..dynamics_codegen::Source::default()
    };
    dynamics_codegen::load(&source).expect("reads").robot
}

#[test]
fn options_then_the_urdf_then_the_defaults() {
    let half = std::f64::consts::FRAC_PI_2;
    let none = joint_limits(&robot(), None, [None; 4]).expect("defaults");
    assert_eq!(none[0].limits.lower, -half);
    assert_eq!(
        [
            none[1].limits.upper,
            none[1].limits.velocity,
            none[1].limits.acceleration
        ],
        [0.1, 0.2, 1.0]
    );
    assert!(none.iter().all(|j| j.origins == [Origin::Default; 4]));
    // The file: a range on joint 1, only one end on joint 2 (no range), speeds on both.
    let urdf = [
        Limit {
            lower: Some(-2.0),
            upper: Some(3.0),
            velocity: Some(1.5),
            effort: None,
        },
        Limit {
            lower: Some(0.0),
            upper: None,
            velocity: Some(0.3),
            effort: None,
        },
    ];
    let upper = [4.0];
    let accelerations = [2.0, 0.5];
    let asked = [None, Some(&upper[..]), None, Some(&accelerations[..])];
    let got = joint_limits(&robot(), Some(&urdf), asked).expect("limits");
    let want = [
        (
            -2.0,
            4.0,
            1.5,
            2.0,
            [Origin::Urdf, Origin::Option, Origin::Urdf],
        ),
        (
            -0.1,
            4.0,
            0.3,
            0.5,
            [Origin::Default, Origin::Option, Origin::Urdf],
        ),
    ];
    for (j, (lower, upper, velocity, acceleration, origins)) in want.into_iter().enumerate() {
        let l = got[j].limits;
        assert_eq!(
            [l.lower, l.upper, l.velocity, l.acceleration],
            [lower, upper, velocity, acceleration]
        );
        assert_eq!(got[j].origins[..3], origins, "{j}");
        assert_eq!(got[j].origins[3], Origin::Option);
    }
}

/// A mimic joint (the second, `q₂ = −0.5 q₁ + 0.2`) is no row: its URDF range [−1, 0.6]
/// and speed 0.4 bound joint 1 through its rule, to [(0.6 − 0.2)/−0.5, (−1 − 0.2)/−0.5] =
/// [−0.8, 2.4] within joint 1's own [−2, 3], and 0.4/0.5 = 0.8 rad/s below its 1.5; the
/// options are per coordinate.
#[test]
fn a_mimic_joints_limits_bound_the_joint_it_follows() {
    let text = "name = \"rrp\"\ngravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\n\
                mass = 1\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\
                mimic = { joint = 1, multiplier = -0.5, offset = 0.2 }\n\
                [[joints]]\ntype = \"prismatic\"\nmass = 1\n";
    let source = dynamics_codegen::Source {
        path: "rrp.toml",
        text: Some(text),
        ..dynamics_codegen::Source::default()
    };
    let robot = dynamics_codegen::load(&source).expect("reads").robot;
    let limit = |lower, upper, velocity| Limit {
        lower: Some(lower),
        upper: Some(upper),
        velocity: Some(velocity),
        effort: None,
    };
    let urdf = [
        limit(-2.0, 3.0, 1.5),
        limit(-1.0, 0.6, 0.4),
        Limit::default(),
    ];
    let got = joint_limits(&robot, Some(&urdf), [None; 4]).expect("limits");
    assert_eq!(got.len(), 2);
    let l = got[0].limits;
    let want = [-0.8, 2.4, 0.8, 5.0];
    for (x, w) in [l.lower, l.upper, l.velocity, l.acceleration]
        .iter()
        .zip(want)
    {
        assert!((x - w).abs() < 1e-12, "{l:?}");
    }
    assert_eq!(
        got[0].origins,
        [Origin::Urdf, Origin::Urdf, Origin::Urdf, Origin::Default]
    );
    assert_eq!(got[1].limits.upper, 0.1);
    let three = [1.0, 1.0, 1.0];
    let Err(Error::Setting(e)) = joint_limits(&robot, None, [None, None, Some(&three[..]), None])
    else {
        panic!("three speeds for two coordinates")
    };
    assert!(e.contains("one for each of the 2 coordinates"), "{e}");
}
