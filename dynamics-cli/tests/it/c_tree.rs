//! The C header of a robot past sixteen joints: Baxter with its grippers' fingers free (19
//! joints, a tree: the limit is 16 along a path), with its derivatives. Its tangents in lanes
//! are 24 wide and read the rows of an identity table of their own width
//! (`dynamics_unit24`, beside the serial robots' `dynamics_unit`, which keeps its width in
//! every header). Compiled by the first compiler found every way its builds go (the lanes
//! among them), unoptimized, and checked against the traced graph at five of the reference
//! data's states.

use crate::c_support::{self, check_against_graph, compile_and_run_builds, root, Reach, State};
use serde_json::Value;

/// The first `count` samples of `tests/data/trees/<file>` as states, their torques with the
/// URDF's joint friction (which the data give apart and the robot's τ includes).
fn states(file: &str, count: usize) -> Vec<State> {
    let path = root().join("tests/data/trees").join(file);
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("data")).expect("JSON");
    let vector = |v: &Value| -> Vec<f64> {
        let items = v.as_array().expect("an array");
        items
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    let samples = json["samples"].as_array().expect("samples");
    samples
        .iter()
        .take(count)
        .map(|s| State {
            q: vector(&s["q"]),
            qd: vector(&s["qd"]),
            qdd: vector(&s["qdd"]),
            // The regressor's data have no friction apart: their τ is the rigid bodies'.
            tau: (vector(&s["tau"]).iter())
                .zip(s.get("friction").map_or_else(|| vec![0.0; 64], vector))
                .map(|(t, f)| t + f)
                .collect(),
        })
        .collect()
}

#[test]
fn baxter_s_header_with_derivatives_past_sixteen_joints() {
    let robot = c_support::urdf_tree_robot_with(
        "robots/urdf/trees/baxter_free_fingers.urdf",
        "base",
        &["derivatives"],
    );
    let header = &robot.header;
    assert!(
        header.contains("#define DYNAMICS_UNIT24_H"),
        "no wide table's guard"
    );
    assert!(header.contains("static const double dynamics_unit24[24][24] = {"));
    assert!(header.contains("static const float dynamics_unit24_f32[24][24] = {"));
    // The last direction's unit vector is read, and the serial robots' table is not there.
    assert!(header.contains("dynamics_unit24[18][k_]"));
    assert!(!header.contains("dynamics_unit["));
    let states = states("baxter_no_mimic.json", 5);
    let runs = compile_and_run_builds(&robot, &states, Reach::First);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: Baxter's C header is not checked");
        return;
    }
    assert!(
        runs.iter()
            .any(|r| r.label.contains("DYNAMICS_TANGENT_LANES=1")),
        "no build with the tangents in lanes"
    );
    for run in &runs {
        check_against_graph(&robot, &states, run);
    }
}

/// The Panda of its URDF, its second finger mimicking the first (8 coordinates, 9 links), with
/// its regressor and base parameters: a block per link, a row per coordinate, and the joints'
/// rows stated; compiled and checked against the traced graph (which `mimic_regressor.rs`
/// checks against Pinocchio) at the regressor data's states.
#[test]
fn the_mimic_pandas_regressor_in_c() {
    let robot = c_support::urdf_tree_robot_with(
        "robots/urdf/panda.urdf",
        "panda_link0",
        &["regressor", "base_parameters"],
    );
    let header = &robot.header;
    assert!(
        header.contains("double y[8][9][10]"),
        "no 8 x 9 x 10 regressor"
    );
    assert!(header.contains("static const int panda_joint_rows[9] = {0, 1, 2, 3, 4, 5, 6, 7, 7};"));
    let states = states("panda_fingers_regressor.json", 3);
    let runs = compile_and_run_builds(&robot, &states, Reach::First);
    for run in &runs {
        check_against_graph(&robot, &states, run);
    }
}
