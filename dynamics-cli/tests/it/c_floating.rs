//! `dynamics emit --lang c ROBOT --floating`: the C header of a robot on a free-flying base
//! (`FloatingDynamics`' M, h, τ, g, M⁻¹ and the forward dynamics, `q` of `n + 7` elements),
//! compiled by the C compilers found and run at the 12 states of Pinocchio 4.1's reference data
//! (`tests/data/floating/`, by `make.py`). Every function, `double` and `float`, against the
//! traced graph (as `c_header.rs` checks a fixed base's, its batch twin bit for bit), and the
//! `double` results against Pinocchio's `crba`, `nonLinearEffects`, `rnea`,
//! `computeGeneralizedGravity`, `computeMinverse` and `aba` (at the data's `tau_in`) to 1e-12
//! of each result's largest element; with `--with derivatives`, `computeRNEADerivatives` and
//! `computeABADerivatives` too. Solo 12's, ANYmal B's and the G1's headers with the extras
//! (`--kinematics --contacts --configuration`), which `c_floating_extras.rs`' driver checks.
//!
//! Without any C compiler the test says so and passes; CI has gcc.

use crate::c_floating_extras as extras;
use crate::c_support::{
    check_against_graph, compile_and_run_builds, emitted_header, families, printed, root,
    scaled_error, Reach, Robot, Run, State,
};
use dynamics_codegen::method::Method;
use dynamics_codegen::pipeline::{self, Source};
use serde_json::Value;

/// The robot of `file` on a free-flying base, its header written by `dynamics emit --lang c
/// --floating` (with the opt-in families `with`), its equations traced in process.
fn floating_robot(file: &str, with: &[&str]) -> Robot {
    floating_robot_with(file, &["--floating"], with)
}

/// [`floating_robot`], the command's options `options` (`--floating` and the extras').
fn floating_robot_with(file: &str, options: &[&str], with: &[&str]) -> Robot {
    let header = emitted_header(file, options, with);
    let path = root().join(file);
    let path = path.to_str().expect("a UTF-8 path");
    let loaded = pipeline::load(&Source::file(path)).expect("a valid description");
    let eq = loaded
        .floating_equations_with(families(with))
        .expect("a floating base");
    Robot::emitted(&loaded.robot.name, eq, header)
}

/// A JSON vector or matrix, rows first.
fn flat(value: &Value) -> Vec<f64> {
    match value {
        Value::Array(items) => items.iter().flat_map(flat).collect(),
        x => vec![x.as_f64().expect("a number")],
    }
}

/// The samples of `data` (under `tests/data/floating/`) and their states: `q`, `v`, `a`, and
/// the generalized force the forward dynamics are called with, `tau_in` where the data have
/// one, else `tau` (whose forward dynamics are `a`).
fn samples(data: &str) -> (Vec<Value>, Vec<State>) {
    let (samples, _) = samples_of(data);
    states_of(samples)
}

/// The states of `samples`, as [`samples`] reads them.
fn states_of(samples: Vec<Value>) -> (Vec<Value>, Vec<State>) {
    let states = samples
        .iter()
        .map(|s| State {
            q: flat(&s["q"]),
            qd: flat(&s["v"]),
            qdd: flat(&s["a"]),
            tau: flat(s.get("tau_in").unwrap_or(&s["tau"])),
        })
        .collect();
    (samples, states)
}

/// Compiles and runs `robot`'s header at the states of `data` as far as `reach` says; checks
/// every function against the graph and each of `table`'s (method, key of `data`) against
/// Pinocchio's values; the runs, for the checks of the functions beyond the table's.
fn check(robot: &Robot, data: &str, reach: Reach, table: &[(Method, &str)]) -> Vec<Run> {
    check_samples(robot, samples(data), reach, table)
}

/// [`check`] at the samples given and their states.
fn check_samples(
    robot: &Robot,
    (samples, states): (Vec<Value>, Vec<State>),
    reach: Reach,
    table: &[(Method, &str)],
) -> Vec<Run> {
    let runs = compile_and_run_builds(robot, &states, reach);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the floating C header is not checked");
        return runs;
    }
    for run in &runs {
        check_against_graph(robot, &states, run);
        for (s, sample) in samples.iter().enumerate() {
            for &(method, key) in table {
                let name = format!("{}_{}", robot.name, method.name());
                let (status, got) = printed(&run.printed, &name, 0, s);
                assert_eq!(*status, 0, "{}: {name} at sample {s}", run.label);
                let e = scaled_error(got, &flat(&sample[key]));
                assert!(
                    e <= 1e-12,
                    "{}: {name} at sample {s}: off by {e:e}",
                    run.label
                );
            }
        }
    }
    runs
}

/// The methods every floating header has, and the data's key of each.
const DYNAMICS: [(Method, &str); 6] = [
    (Method::FloatingMassMatrix, "M"),
    (Method::FloatingBiasForces, "h"),
    (Method::FloatingInverseDynamics, "tau"),
    (Method::FloatingGravity, "g"),
    (Method::FloatingMassMatrixInverse, "M_inv"),
    (Method::FloatingForwardDynamics, "a_fd"),
];

/// Solo 12's header with the kinematics, the contacts and the configuration space too
/// (`c_floating_extras.rs` checks them, in the same driver).
#[test]
fn solo12_floating_header_matches_pinocchio() {
    let options = [
        "--floating",
        "--kinematics",
        "--contacts",
        "--configuration",
    ];
    let mut robot = floating_robot_with("robots/urdf/floating/solo12.urdf", &options, &[]);
    assert!(
        robot
            .header
            .contains("--floating --kinematics --contacts --configuration"),
        "its command names them"
    );
    let signature = "_inverse_dynamics(const double q[19], const double qd[18], \
                     const double qdd[18], double tau[18])";
    assert!(robot.header.contains(signature), "{}", robot.header);
    let upper = robot.name.to_ascii_uppercase();
    assert!(robot
        .header
        .contains(&format!("#define {upper}_FRAME_HR_FOOT 3")));
    let data = extras::solo12();
    robot.calls = extras::calls(&robot.name, &data, robot.eq.dof);
    for run in check(&robot, "solo12.json", Reach::Compilers, &DYNAMICS) {
        extras::check(&run.printed, &run.label, &data);
    }
}

/// A robot with a parameter (`params`): the configuration's functions and their batch twins
/// take none (the same for every robot).
#[test]
fn the_configurations_batch_twins_take_no_parameters() {
    let file = "tests/data/floating/solo12_joint_terms.toml";
    let text = std::fs::read_to_string(root().join(file)).expect("the description");
    let with_parameter = text.replacen("mass = 0.14853845", "mass = \"m1\"", 1);
    assert_ne!(with_parameter, text, "a mass to name");
    let path = std::env::temp_dir().join(format!("c_floating_{}.toml", std::process::id()));
    std::fs::write(&path, with_parameter).expect("a temporary file");
    let header = emitted_header(
        path.to_str().expect("a UTF-8 path"),
        &["--floating", "--configuration"],
        &[],
    );
    std::fs::remove_file(&path).ok();
    assert!(
        header.contains("const double params[1]"),
        "it has a parameter"
    );
    for call in [
        "solo_integrate(q + 19 * i, v + 18 * i, out + 19 * i);",
        "solo_difference_jacobian_q1(q0 + 19 * i, q1 + 19 * i, (double (*)[18])(out + 324 * i));",
    ] {
        assert!(header.contains(call), "{call}");
    }
}

/// The table's functions are the same text with the extras as without.
#[test]
fn the_extras_leave_the_tables_functions_as_they_are() {
    let file = "robots/floating/solo12.toml";
    let plain = emitted_header(file, &["--floating"], &[]);
    let more = emitted_header(file, &["--floating", "--kinematics"], &[]);
    // From the first function to the extras (the end of the guard where there are none).
    let body = |h: &str| -> String {
        let start = h
            .find("#ifndef DYNAMICS_TRIG_H")
            .expect("the sines' functions");
        let end = h
            .find("/* The frames of")
            .or_else(|| h.find("#endif /* DYNAMICS_ROBOT_"))
            .expect("the guard's end");
        h[start..end].to_owned()
    };
    assert!(body(&plain) == body(&more), "the table's functions differ");
    let refused = std::process::Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(["emit", "--lang", "c", file, "--kinematics"])
        .current_dir(root())
        .output()
        .expect("run dynamics");
    assert!(!refused.status.success(), "--kinematics needs --floating");
}

/// The options of a header with every extra.
const EXTRAS: [&str; 4] = [
    "--floating",
    "--kinematics",
    "--contacts",
    "--configuration",
];

/// The table's methods checked where the data have no `a_fd` or `M_inv` (the forward
/// dynamics at `tau`, whose result is `a`).
const DYNAMICS_AT_TAU: [(Method, &str); 5] = [
    (Method::FloatingMassMatrix, "M"),
    (Method::FloatingBiasForces, "h"),
    (Method::FloatingInverseDynamics, "tau"),
    (Method::FloatingGravity, "g"),
    (Method::FloatingForwardDynamics, "a"),
];

/// ANYmal B with every extra (its legs in Pinocchio's `q` in another order than the file's:
/// `anymal_b_extras.json` has them in the file's), one compiler.
#[test]
fn anymal_b_floating_header_matches_pinocchio() {
    let mut robot = floating_robot_with("robots/urdf/floating/anymal_b.urdf", &EXTRAS, &[]);
    let data = extras::extras("anymal_b");
    robot.calls = extras::calls(&robot.name, &data, robot.eq.dof);
    for run in check(&robot, "anymal_b.json", Reach::First, &DYNAMICS_AT_TAU) {
        extras::check(&run.printed, &run.label, &data);
    }
}

/// The Unitree G1 (29 joints, 9 frames: its ankles, hands, head and sensors) with every
/// extra, one compiler.
#[test]
fn g1_floating_header_matches_pinocchio() {
    let mut robot = floating_robot_with("robots/urdf/floating/g1_29dof.urdf", &EXTRAS, &[]);
    // Its M's condition number reaches 3.5e5: M⁻¹ was 2.3e-12 from the graph's evaluation.
    robot.solve_tolerance = 1e-10;
    let mut data = extras::extras("g1_29dof");
    data.solve_tolerance = 1e-10;
    robot.calls = extras::calls(&robot.name, &data, robot.eq.dof);
    // The forward dynamics against Pinocchio's `aba` at the derivatives' `tau_in` (`ddq`):
    // at `tau = rnea(q, v, a)` it is 2.1e-11 from `a`, the rounding of `tau` times M's
    // condition number.
    let (mut samples, _) = samples_of("g1_29dof.json");
    let (derivatives, _) = samples_of("g1_29dof_derivatives.json");
    for (sample, d) in samples.iter_mut().zip(&derivatives) {
        sample["tau_in"] = d["tau_in"].clone();
        sample["ddq"] = d["ddq"].clone();
    }
    let mut table = DYNAMICS_AT_TAU;
    table[4] = (Method::FloatingForwardDynamics, "ddq");
    for run in check_samples(&robot, states_of(samples), Reach::First, &table) {
        extras::check(&run.printed, &run.label, &data);
    }
}

/// `--with derivatives`: `inverse_dynamics_derivatives` (`∂τ/∂q` along the tangent, `∂τ/∂v`)
/// and `forward_dynamics_derivatives` (`a`, `∂a/∂q`, `∂a/∂v`, `∂a/∂τ`) at the data's
/// `tau_in` against Pinocchio's `computeRNEADerivatives` and `computeABADerivatives`
/// (`solo12_derivatives.json`), each matrix to 1e-12 of its largest element, as the derive's
/// are (`tests/tests/it/floating_derivatives.rs`).
#[test]
fn solo12_floating_derivatives_header_matches_pinocchio() {
    let robot = floating_robot("robots/urdf/floating/solo12.urdf", &["derivatives"]);
    let (_, mut states) = samples("solo12.json");
    let (derivatives, _) = samples_of("solo12_derivatives.json");
    for (state, d) in states.iter_mut().zip(&derivatives) {
        state.tau = flat(&d["tau_in"]);
    }
    let runs = compile_and_run_builds(&robot, &states, Reach::First);
    let nv = robot.eq.dof;
    for run in &runs {
        check_against_graph(&robot, &states, run);
        for (s, d) in derivatives.iter().enumerate() {
            let parts = [
                (
                    "inverse_dynamics_derivatives",
                    0,
                    vec!["dtau_dq", "dtau_dv"],
                ),
                ("forward_dynamics_derivatives", 0, vec!["ddq"]),
                (
                    "forward_dynamics_derivatives",
                    1,
                    vec!["ddq_dq", "ddq_dv", "ddq_dtau"],
                ),
            ];
            for (method, part, keys) in parts {
                let name = format!("{}_{method}", robot.name);
                let (status, got) = printed(&run.printed, &name, part, s);
                assert_eq!(*status, 0, "{}: {name} at sample {s}", run.label);
                let size = got.len() / keys.len();
                assert!(
                    size == nv || size == nv * nv,
                    "{name}: {} numbers",
                    got.len()
                );
                for (k, key) in keys.iter().enumerate() {
                    let e = scaled_error(&got[k * size..(k + 1) * size], &flat(&d[*key]));
                    assert!(
                        e <= 1e-12,
                        "{}: {name} {key} at sample {s}: off by {e:e}",
                        run.label
                    );
                }
            }
        }
    }
}

/// The samples of `data` under `tests/data/floating/`, and the data.
fn samples_of(data: &str) -> (Vec<Value>, Value) {
    let text = std::fs::read_to_string(root().join("tests/data/floating").join(data))
        .expect("reference data");
    let json: Value = serde_json::from_str(&text).expect("JSON");
    (json["samples"].as_array().expect("samples").clone(), json)
}
