//! The C header of a robot whose values are struct fields (read through the derive's front
//! end: description files have none): every function takes `const double params[K]` first, in
//! the order the header's comment states, and a joint's angle offset, a field or a constant
//! other than a quarter turn, goes into its sine and cosine. Compiled and checked against the
//! graph as `c_header.rs` does, with parameter values that are not the defaults.

use crate::c_support;

use c_support::{check_against_graph, compile_and_run, Reach, Robot, State};
use dynamics_codegen::{derive, front};

/// A 3R arm with a field in an angle offset, a length, a mass and a centre of mass, a
/// constant offset of 0.3 rad, viscous friction from a field and a geared motor.
fn arm() -> Robot {
    let input: syn::DeriveInput = syn::parse_quote! {
        #[dynamics(
            gravity = [0, 0, -9.81],
            dh = [
                [q + theta0, 0.3, l1, 90 deg],
                [q, 0, 0.4, 0],
                [q + 0.3, 0.05, 0.2, 0],
            ],
            link(mass = m1, com = [0, 0, -0.1], inertia = [0.02, 0.02, 0.01, 0, 0, 0]),
            link(mass = 2.5, com = [-0.2, 0, cx2], inertia = [0.01, 0.05, 0.05, 0, 0, 0],
                 friction = (viscous = fv2, coulomb = 0.4)),
            link(mass = 1 + payload, com = [-0.1, 0, 0], inertia = [0.002, 0.01, 0.01, 0, 0, 0],
                 rotor_inertia = 0.0001, gear_ratio = 50),
        )]
        struct Arm {
            theta0: f64,
            l1: f64,
            m1: f64,
            cx2: f64,
            fv2: f64,
            payload: f64,
        }
    };
    let parsed = front::parse(&input).unwrap_or_else(|_| panic!("a valid robot"));
    let eq = derive(&parsed.robot);
    assert!(
        eq.angle_offsets.iter().flatten().count() >= 2,
        "offsets traced"
    );
    // In the order of the fields the equations read, which the header states.
    let values = |field: &str| match field {
        "theta0" => 0.25,
        "l1" => 0.15,
        "m1" => 3.2,
        "cx2" => 0.02,
        "fv2" => 0.7,
        "payload" => 0.5,
        other => panic!("no value for `{other}`"),
    };
    let params = eq.fields.iter().map(|f| values(f)).collect();
    Robot::new("Arm", eq, params)
}

#[test]
fn parameters_come_first_in_the_stated_order() {
    let robot = arm();
    let k = robot.eq.fields.len();
    for (i, field) in robot.eq.fields.iter().enumerate() {
        let line = format!(" *   params[{i}] = {field}\n");
        assert!(robot.header.contains(&line), "the header states {line:?}");
    }
    let signature = format!(
        "static inline void arm_inverse_dynamics(const double params[{k}], const double q[3], \
         const double qd[3], const double qdd[3], double tau[3])"
    );
    assert!(robot.header.contains(&signature), "{signature}");
    assert!(robot.header.contains("const float params[6]"));
    // The offsets: a field's read as a parameter, the constant's as a literal; a group of
    // joints padded with its last angle.
    assert!(robot
        .header
        .contains("{q[0] + p_theta0, q[1], q[2] + 0.3, q[2] + 0.3}"));
    assert!(robot
        .header
        .contains("{q[1], q[2] + 0.3f, q[2] + 0.3f, q[2] + 0.3f}"));
}

#[test]
fn a_robot_with_parameters_computes_the_graphs_values() {
    let robot = arm();
    let states: Vec<State> = (0..4)
        .map(|k| {
            let x = f64::from(k);
            State {
                q: vec![0.3 - 0.2 * x, 0.7 * x - 0.5, 1.1 - 0.3 * x],
                qd: vec![0.4 * x - 0.6, 0.2, -0.3 * x],
                qdd: vec![1.0, -0.5 * x, 0.25],
                tau: vec![2.0 - x, 3.0, -1.0],
            }
        })
        .collect();
    let runs = compile_and_run(&robot, &states);
    if runs.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C header is not checked");
        return;
    }
    for run in &runs {
        check_against_graph(&robot, &states, run);
    }
}

/// The opt-in families too (`--with derivatives,regressor,base_parameters,tip_kinematics`):
/// their functions, stacks of matrices and a solve with its derivatives among them, against the
/// graph: a two-link arm's header built by every compiler (each one's flow analyses see the
/// families' code), PUMA 560's by one, unoptimized (it is large).
#[test]
fn the_opt_in_families_compute_the_graphs_values() {
    let with = [
        "derivatives",
        "regressor",
        "base_parameters",
        "tip_kinematics",
    ];
    for (file, reach) in [
        ("robots/two_link_friction.toml", Reach::Compilers),
        ("robots/puma560.toml", Reach::First),
    ] {
        let robot = c_support::robot_with(file, &with);
        let n = robot.eq.dof;
        for name in [
            "inverse_dynamics_derivatives",
            "base_regressor_f32",
            "joint_torques_for_tip_wrenches",
        ] {
            let name = format!("{}_{name}", robot.name);
            assert!(robot.functions.iter().any(|f| f.name == name), "{name}");
        }
        let states: Vec<State> = (0..3)
            .map(|k| {
                let x = f64::from(k);
                let joints = (0..n).map(|i| f64::from(u32::try_from(i).expect("few joints")));
                State {
                    q: joints.clone().map(|i| 0.3 * x - 0.1 * i).collect(),
                    qd: joints.clone().map(|i| 0.2 - 0.15 * x * i).collect(),
                    qdd: joints.clone().map(|i| 1.0 - 0.3 * i).collect(),
                    tau: joints.map(|i| 5.0 - x - i).collect(),
                }
            })
            .collect();
        for run in &c_support::compile_and_run_builds(&robot, &states, reach) {
            check_against_graph(&robot, &states, run);
        }
    }
}
