//! The floating-base kinematic outputs traced into Solo 12's floating graph, evaluated at the
//! states of `tests/data/floating/solo12.json` and checked against Pinocchio 4.1
//! (`solo12_kinematics.json`): the closed form the derive emits, before it is emitted.

use crate::unit::algo::floating_kinematics_tests::{check, data, flat, solo12_with_feet, FEET};
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::trace::derive_floating;

#[test]
fn solo12_traced_against_pinocchio() {
    let (robot, flyer) = solo12_with_feet();
    let mut eq = derive_floating(&robot, &flyer);
    let out = eq.floating_kinematics(&robot, &flyer);
    assert_eq!(out.frame_names, FEET);
    assert!(eq.angle_offsets.iter().all(Option::is_none));
    assert!(eq.fields.is_empty(), "Solo 12's numbers are constants");
    let (states, reference) = (data("solo12.json"), data("solo12_kinematics.json"));
    let states = states["samples"].as_array().expect("samples");
    let samples = reference["samples"].as_array().expect("samples");
    for (k, (state, expected)) in states.iter().zip(samples).enumerate() {
        let (q, v) = (flat(&state["q"]), flat(&state["v"]));
        // The graph's coordinates: `Q(k)` is q's entry k + 1, joint i at 6 + i.
        let values = eq.graph.eval(|var| match var {
            Var::Q(i) => q[usize::from(i) + 1],
            Var::SinQ(i) => q[usize::from(i) + 1].sin(),
            Var::CosQ(i) => q[usize::from(i) + 1].cos(),
            Var::Qd(i) => v[usize::from(i)],
            // The acceleration and the generalized force, which the kinematics do not read.
            Var::Qdd(_) | Var::Tau(_) => 0.0,
            other => panic!("{other:?} is not an input of the floating equations"),
        });
        let at = |ids: &[NodeId]| -> Vec<f64> { ids.iter().map(|id| values[id.index()]).collect() };
        let flat_at = |m: &[Vec<NodeId>]| -> Vec<f64> { m.iter().flat_map(|r| at(r)).collect() };
        let relative = at(&out.com);
        let com: Vec<f64> = (0..3).map(|i| q[i] + relative[i]).collect();
        check(&format!("#{k} com"), &com, &expected["com"]);
        check(
            &format!("#{k} Jcom"),
            &flat_at(&out.com_jacobian),
            &expected["Jcom"],
        );
        check(
            &format!("#{k} Ag"),
            &flat_at(&out.centroidal_matrix),
            &expected["Ag"],
        );
        check(
            &format!("#{k} dAg v"),
            &at(&out.centroidal_bias),
            &expected["dAg_v"],
        );
        for (f, name) in out.frame_names.iter().enumerate() {
            let e = &expected["frames"][name];
            let what = |x: &str| format!("#{k} {name} {x}");
            let pose = flat_at(&out.frame_poses[f]);
            let rotation: Vec<f64> = pose.chunks(4).flat_map(|r| r[..3].to_vec()).collect();
            let position: Vec<f64> = (0..3).map(|i| q[i] + pose[4 * i + 3]).collect();
            check(&what("rotation"), &rotation, &e["rotation"]);
            check(&what("translation"), &position, &e["translation"]);
            check(
                &what("J local"),
                &flat_at(&out.jacobians_local[f]),
                &e["J_local"],
            );
            check(
                &what("J world"),
                &flat_at(&out.jacobians_world[f]),
                &e["J_world_aligned"],
            );
            check(
                &what("dJv local"),
                &at(&out.biases_local[f]),
                &e["dJv_local"],
            );
            check(
                &what("dJv world"),
                &at(&out.biases_world[f]),
                &e["dJv_world_aligned"],
            );
        }
    }
}
