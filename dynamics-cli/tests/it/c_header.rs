//! `dynamics emit --lang c`: the headers of PUMA 560, the Panda, four URDF robots and a two-link
//! arm with friction, compiled with a driver (PUMA 560's and the small ones' by every compiler
//! found: gcc and clang as C99, `-Wall -Wextra -Wpedantic -Werror`, plus `-Wdouble-promotion`
//! so that the `float` functions never widen, with `<math.h>` and with their own sines and
//! cosines, optimized once; g++ as C++17; the others' by the first, unoptimized), and run at
//! the states of the reference data. What the driver prints is
//! checked three ways:
//!
//! * every function, in `double` and in `float`, against the traced graph evaluated in `f64`
//!   (the same closed forms: this checks the C printer, operation by operation): the
//!   `double` results bit for bit, compiled without contraction into multiply-adds;
//! * τ, M, g, C q̇ + g, C q̇, the energies, the hand's pose and Jacobian, and the forward
//!   dynamics against Pinocchio's values (`tests/data/reference/data/puma560.json`,
//!   `tests/data/panda/data.json`, and for the UR10, Panda, Z1 and SO-101 URDF files
//!   `tests/data/urdf/`, whose friction τ adds), to 1e-10 of each result's largest element;
//! * friction against its formula in the description file, at rest and in motion;
//! * the simplified models a description file asks for (`[simplify]`; a mimic robot's too) against the exact
//!   functions, within the proven bounds the header states above them.
//!
//! Without any C compiler the test says so and passes; CI has gcc.

use crate::c_support;

use c_support::{
    check_against_graph, compile_and_run, compile_and_run_builds, printed, robot, root,
    scaled_error, urdf_robot, Printed, Reach, Robot, State,
};
use dynamics_codegen::method::Method;
use serde_json::Value;

/// The samples of a reference data file as states.
fn samples(data: &str) -> (Vec<Value>, Vec<State>) {
    let text = std::fs::read_to_string(root().join(data)).expect("reference data");
    let json: Value = serde_json::from_str(&text).expect("JSON");
    let samples = json["samples"].as_array().expect("samples").clone();
    let vector = |v: &Value| -> Vec<f64> {
        let items = v.as_array().expect("an array");
        items
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    let states = samples
        .iter()
        .map(|s| State {
            q: vector(&s["q"]),
            qd: vector(&s["qd"]),
            qdd: vector(&s["qdd"]),
            tau: applied(s),
        })
        .collect();
    (samples, states)
}

/// The torques that give the sample's q̈: its τ, plus the joints' friction where the data give
/// it apart (the URDF robots'), which the robot's τ includes.
fn applied(sample: &Value) -> Vec<f64> {
    let tau = flat(&sample["tau"], usize::MAX);
    match sample.get("friction") {
        Some(f) => tau
            .iter()
            .zip(flat(f, usize::MAX))
            .map(|(t, f)| t + f)
            .collect(),
        None => tau,
    }
}

/// The elements of a JSON vector or matrix (its first `rows` rows), rows first.
fn flat(value: &Value, rows: usize) -> Vec<f64> {
    match value {
        Value::Array(items) => items
            .iter()
            .take(rows)
            .flat_map(|x| flat(x, usize::MAX))
            .collect(),
        x => vec![x.as_f64().expect("a number")],
    }
}

/// τ, M, g, C q̇ + g, C q̇, the energies, the hand's pose and Jacobian and the forward
/// dynamics against Pinocchio's, to 1e-10 (the forward dynamics, a solve, to 1e-8).
fn check_against_pinocchio(robot: &Robot, samples: &[Value], out: &Printed, cc: &str) {
    let all = usize::MAX;
    for (s, sample) in samples.iter().enumerate() {
        let g = flat(&sample["g"], all);
        let h = flat(&sample["h"], all);
        let table = [
            (Method::InverseDynamics, applied(sample), 1e-10),
            (Method::MassMatrix, flat(&sample["M"], all), 1e-10),
            (Method::GravityTorques, g.clone(), 1e-10),
            (Method::BiasTorques, h.clone(), 1e-10),
            (
                Method::KineticEnergy,
                flat(&sample["kinetic_energy"], all),
                1e-10,
            ),
            (
                Method::PotentialEnergy,
                flat(&sample["potential_energy"], all),
                1e-10,
            ),
            (Method::HandPose, flat(&sample["ee_pose"], 3), 1e-10),
            (
                Method::HandJacobianInBase,
                flat(&sample["jacobian"], all),
                1e-10,
            ),
            (Method::ForwardDynamics, flat(&sample["qdd"], all), 1e-8),
        ];
        for (method, want, tolerance) in table {
            let name = format!("{}_{}", robot.name, method.name());
            let (_, got) = printed(out, &name, 0, s);
            let e = scaled_error(got, &want);
            assert!(e <= tolerance, "{cc}: {name} at sample {s}: off by {e:e}");
        }
        // C q̇ is small beside g: compared as C q̇ + g with h.
        let name = format!("{}_coriolis_torques", robot.name);
        let (_, cqd) = printed(out, &name, 0, s);
        let got: Vec<f64> = cqd.iter().zip(&g).map(|(c, g)| c + g).collect();
        let e = scaled_error(&got, &h);
        assert!(e <= 1e-10, "{cc}: {name} at sample {s}: off by {e:e}");
    }
}

/// Checks `robot`'s header against the graph and Pinocchio's reference `data`, built as far as
/// `reach` says.
fn check_robot(robot: &Robot, data: &str, reach: Reach) {
    let (samples, states) = samples(data);
    let runs = compile_and_run_builds(robot, &states, reach);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C header of {data} is not checked");
        return;
    }
    for run in &runs {
        check_against_graph(robot, &states, run);
        check_against_pinocchio(robot, &samples, &run.printed, &run.label);
    }
}

#[test]
fn puma560_header_matches_pinocchio() {
    let robot = robot("robots/puma560.toml");
    check_robot(
        &robot,
        "tests/data/reference/data/puma560.json",
        Reach::EveryWay,
    );
}

#[test]
fn panda_header_matches_pinocchio() {
    // Its header's code is of PUMA 560's kinds, which that one builds every way.
    let robot = robot("robots/panda.toml");
    check_robot(&robot, "tests/data/panda/data.json", Reach::First);
}

/// The URDF robots, lowered to their own D-H tables (angle offsets, merged fixed links, the
/// hand at the tip link), against Pinocchio's model of the same files: the UR10, the Panda
/// (viscous damping), the Z1 (viscous and Coulomb friction) and the SO-101 (snapped angles),
/// with the first compiler found only (their builds every way add nothing the reference
/// robots' do not cover).
#[test]
fn urdf_headers_match_pinocchio() {
    for (file, base, tip, data) in [
        (
            "robots/urdf/ur10.urdf",
            "base_link",
            "tool0",
            "tests/data/urdf/ur10.json",
        ),
        (
            "robots/urdf/panda.urdf",
            "panda_link0",
            "panda_link8",
            "tests/data/urdf/panda.json",
        ),
        (
            "robots/urdf/z1.urdf",
            "link00",
            "link06",
            "tests/data/urdf/z1.json",
        ),
        (
            "robots/urdf/so101.urdf",
            "base_link",
            "gripper_link",
            "tests/data/urdf/so101.json",
        ),
    ] {
        check_robot(&urdf_robot(file, base, tip), data, Reach::First);
    }
}

/// `robots/two_link_friction.toml`: joint 1 has `0.3 qd + 1.5 sign(qd) - 0.2`, joint 2
/// `0.1 qd + 0.8 tanh(qd / 0.01)`; at rest, sign(0) = 0. τ is `M q̈ + C q̇ + g` plus that.
#[test]
fn friction_in_the_header_is_the_description_files() {
    let robot = robot("robots/two_link_friction.toml");
    let states = [
        ([0.0, 0.0], [0.3, -0.4]),
        ([0.5, -0.003], [1.0, 2.0]),
        ([-1.2, 0.7], [0.0, -1.0]),
    ]
    .iter()
    .enumerate()
    .map(|(k, (qd, qdd))| State {
        q: vec![0.4 * k as f64 - 0.3, 1.1 - 0.6 * k as f64],
        qd: qd.to_vec(),
        qdd: qdd.to_vec(),
        tau: vec![2.0, -1.0],
    })
    .collect::<Vec<_>>();
    let runs = compile_and_run(&robot, &states);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C header is not checked");
        return;
    }
    let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
    for run in &runs {
        let (out, cc) = (&run.printed, &run.label);
        check_against_graph(&robot, &states, run);
        for (s, state) in states.iter().enumerate() {
            let [v1, v2] = [state.qd[0], state.qd[1]];
            let want = [
                0.3 * v1 + 1.5 * sign(v1) - 0.2,
                0.1 * v2 + 0.8 * (v2 / 0.01).tanh(),
            ];
            let get = |method: &str| &printed(out, &format!("{}_{method}", robot.name), 0, s).1;
            let e = scaled_error(get("friction_torques"), &want);
            assert!(e <= 1e-12, "{cc}: friction at sample {s}: off by {e:e}");
            let (m, h) = (get("mass_matrix"), get("bias_torques"));
            let rigid: Vec<f64> = (0..2)
                .map(|i| m[2 * i] * state.qdd[0] + m[2 * i + 1] * state.qdd[1] + h[i] + want[i])
                .collect();
            let e = scaled_error(get("inverse_dynamics"), &rigid);
            assert!(
                e <= 1e-12,
                "{cc}: inverse dynamics at sample {s}: off by {e:e}"
            );
        }
    }
}

/// The bounds a simplified function's comment states (`|T1 - T1,simplified| <= 4.2e-1 ...`),
/// in its order.
fn stated_bounds(header: &str, function: &str) -> Vec<f64> {
    let at = header
        .find(&format!(" {function}(const"))
        .expect("the function");
    let comment = &header[header[..at].rfind("/*").expect("its comment")..at];
    comment
        .lines()
        .filter_map(|line| line.split_once(",simplified| <= "))
        .map(|(_, rest)| {
            let number = rest.split_whitespace().next().expect("a bound");
            number.parse().expect("a number")
        })
        .collect()
}

/// `tests/data/simplify/two_link.toml` asks for its simplified models: the header has them,
/// in `double` and `float`, and at states inside the file's envelope they stay within the
/// bounds their comments state of the exact functions, and differ from them (terms dropped).
#[test]
fn simplified_functions_within_their_stated_bounds() {
    // Inside the file's envelope: q1 in [-1, 1], q2 in [-2, 2], |qd| <= 3, |qdd| <= 5.
    let states: Vec<State> = (0..24)
        .map(|k| {
            let x = f64::from(k) / 23.0;
            let wave = |a: f64, b: f64| (a * x * 7.0 + b).sin();
            State {
                q: vec![wave(1.0, 0.2), 2.0 * wave(1.3, 1.1)],
                qd: vec![3.0 * wave(0.7, 2.0), 3.0 * wave(1.9, 0.5)],
                qdd: vec![5.0 * wave(2.3, 1.4), 5.0 * wave(0.4, 2.9)],
                tau: vec![1.0, -1.0],
            }
        })
        .collect();
    simplified_within_bounds("tests/data/simplify/two_link.toml", &states);
}

/// The small mimic arm's (`tests/data/trees/mimic_arm.toml`: 3 coordinates, the mimic joint's
/// `sin(-0.7 q2 + c)` among the pruned terms) likewise, inside its envelope: q in [-1, 1.5],
/// |qd| <= 2, |qdd| <= 5.
#[test]
fn a_mimic_robots_simplified_functions_within_their_stated_bounds() {
    let states: Vec<State> = (0..24)
        .map(|k| {
            let x = f64::from(k) / 23.0;
            let wave = |a: f64, b: f64| (a * x * 7.0 + b).sin();
            let q = |a, b| 0.25 + 1.25 * wave(a, b);
            State {
                q: vec![q(1.0, 0.2), q(1.3, 1.1), q(0.6, 2.5)],
                qd: vec![
                    2.0 * wave(0.7, 2.0),
                    2.0 * wave(1.9, 0.5),
                    2.0 * wave(1.1, 0.1),
                ],
                qdd: vec![
                    5.0 * wave(2.3, 1.4),
                    5.0 * wave(0.4, 2.9),
                    5.0 * wave(1.7, 0.8),
                ],
                tau: vec![1.0, -1.0, 0.5],
            }
        })
        .collect();
    simplified_within_bounds("tests/data/trees/mimic_arm.toml", &states);
}

/// The header of `file` (which asks for its simplified models) compiled and run at `states`:
/// each simplified function within the bounds its comment states of the exact one, and not
/// the exact one.
fn simplified_within_bounds(file: &str, states: &[State]) {
    let robot = robot(file);
    let runs = compile_and_run(&robot, states);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C header is not checked");
        return;
    }
    let n = robot.eq.dof;
    for run in &runs {
        let (out, cc) = (&run.printed, &run.label);
        check_against_graph(&robot, states, run);
        for (exact, simplified) in [
            ("inverse_dynamics", "inverse_dynamics_simplified"),
            ("gravity_torques", "gravity_torques_simplified"),
            ("coriolis_torques", "coriolis_torques_simplified"),
            ("mass_matrix", "mass_matrix_simplified"),
        ] {
            let name = |m: &str| format!("{}_{m}", robot.name);
            let bounds = stated_bounds(&robot.header, &name(simplified));
            let mut largest = 0.0_f64;
            for s in 0..states.len() {
                let (_, want) = printed(out, &name(exact), 0, s);
                let (_, got) = printed(out, &name(simplified), 0, s);
                // M's bounds are its upper triangle's, row by row.
                let elements: Vec<usize> = if want.len() == n {
                    (0..n).collect()
                } else {
                    (0..n)
                        .flat_map(|i| (i..n).map(move |j| i * n + j))
                        .collect()
                };
                assert_eq!(elements.len(), bounds.len(), "{cc}: {simplified}'s bounds");
                for (b, &e) in elements.iter().enumerate() {
                    let off = (want[e] - got[e]).abs();
                    largest = largest.max(off);
                    assert!(
                        off <= bounds[b] * (1.0 + 1e-9) + 1e-12,
                        "{cc}: {simplified} element {e} at state {s}: off by {off:e}, bound {}",
                        bounds[b]
                    );
                }
            }
            assert!(largest > 0.0, "{cc}: {simplified} is the exact {exact}");
        }
    }
}
