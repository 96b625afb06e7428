//! Measurements synthesised from a robot with known parameters, for the tests of
//! `dynamics identify`: a finite Fourier series of joint motions with exact derivatives, and the
//! torques of `Numeric::inverse_dynamics` (recursive Newton-Euler in `f64`, with the actuators,
//! friction and springs of the description), independent of the regressor under test.

use dynamics_codegen::model::Robot;
use dynamics_codegen::numeric::Numeric;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::{Command, Output};

/// A 4-joint arm: a vertical revolute joint, two revolute joints about parallel axes, and a
/// prismatic wrist, with actuator inertia, viscous, Coulomb and offset friction, and a spring.
const ARM: &str = r#"
name = "arm4"
gravity = [0, 0, -9.81]

[[joints]]
type = "revolute"
d = 0.4
alpha = "90 deg"
mass = 3
com = [0, -0.1, 0.02]
inertia = [0.05, 0.04, 0.03, 0.001, 0, 0.002]
actuator_inertia = 0.2
friction_viscous = 0.8
friction_coulomb = 1.2

[[joints]]
type = "revolute"
a = 0.5
mass = 4
com = [-0.25, 0.01, 0.03]
inertia = [0.02, 0.09, 0.08, 0.003, -0.002, 0.001]
actuator_inertia = 0.15
friction_viscous = 0.5
friction_coulomb = 0.9
friction_offset = 0.3
spring_stiffness = 12
spring_rest = 0.2

[[joints]]
type = "revolute"
a = 0.35
alpha = "-90 deg"
mass = 2.5
com = [-0.15, 0, 0.05]
inertia = [0.01, 0.03, 0.025, 0, 0.001, 0]
actuator_inertia = 0.08
friction_viscous = 0.3
friction_coulomb = 0.4

[[joints]]
type = "prismatic"
theta = "90 deg"
mass = 1.2
com = [0.01, 0.02, -0.05]
inertia = [0.004, 0.005, 0.003, 0, 0, 0]
actuator_inertia = 0.5
friction_viscous = 2.0
friction_coulomb = 1.5
"#;

/// A scratch file of this test binary.
pub fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_identify");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name)
}

fn arm_file() -> String {
    let path = scratch("arm4.toml");
    std::fs::write(&path, ARM).expect("write robot");
    path.to_string_lossy().into_owned()
}

/// The arm's description, as text.
pub fn arm_text() -> &'static str {
    ARM
}

pub fn arm() -> Robot {
    dynamics_codegen::front::load("arm4.toml", ARM)
        .expect("the test robot reads")
        .robot
}

/// The arm's description file, written once per test binary.
pub fn arm_file_static() -> &'static str {
    static PATH: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    PATH.get_or_init(arm_file)
}

/// A sample of a trajectory, with exact derivatives.
pub struct State {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
}

/// A finite Fourier series per joint (the excitation of Swevers et al., 1997):
/// `q_j(t) = c_j + Σ_l a_jl sin(l ω t + φ_jl)`, with its exact derivatives; `seed` varies the
/// phases and amplitudes. Joints in `still` keep `q_j = c_j`.
pub fn fourier(n: usize, samples: usize, rate: f64, seed: f64, still: &[usize]) -> Vec<State> {
    let omega = 2.0 * std::f64::consts::PI * 0.25;
    (0..samples)
        .map(|k| {
            let t = k as f64 / rate;
            let mut s = State {
                t,
                q: vec![0.0; n],
                qd: vec![0.0; n],
                qdd: vec![0.0; n],
            };
            for j in 0..n {
                s.q[j] = 0.3 + 0.1 * j as f64;
                if still.contains(&j) {
                    continue;
                }
                for l in 1..=4 {
                    let lw = l as f64 * omega;
                    let a = (0.5 + 0.3 * (seed * (j * 5 + l) as f64).sin()) / l as f64 * 0.6;
                    let phase = seed * (1.0 + j as f64) * (2.0 + l as f64);
                    let x = lw * t + phase;
                    s.q[j] += a * x.sin();
                    s.qd[j] += a * lw * x.cos();
                    s.qdd[j] -= a * lw * lw * x.sin();
                }
            }
            s
        })
        .collect()
}

/// The measured torques: inverse dynamics of the description, plus `noise(j)` per joint.
pub fn torques(
    robot: &Robot,
    states: &[State],
    mut noise: impl FnMut(usize) -> f64,
) -> Vec<Vec<f64>> {
    let numeric = Numeric::new(robot, &[]).expect("no fields");
    states
        .iter()
        .map(|s| {
            let tau = numeric.inverse_dynamics(&s.q, &s.qd, &s.qdd);
            tau.iter().enumerate().map(|(j, t)| t + noise(j)).collect()
        })
        .collect()
}

/// Writes `t, q.., [qd.., qdd..,] tau..` (with the derivatives when `derivatives`).
pub fn write_csv(name: &str, states: &[State], tau: &[Vec<f64>], derivatives: bool) -> String {
    let n = states[0].q.len();
    let names = |p: &str| (1..=n).map(|i| format!("{p}{i}")).collect::<Vec<_>>();
    let mut header = vec!["t".to_string()];
    header.extend(names("q"));
    if derivatives {
        header.extend(names("qd"));
        header.extend(names("qdd"));
    }
    header.extend(names("tau"));
    let mut text = header.join(",") + "\n";
    for (s, tau) in states.iter().zip(tau) {
        let mut row = vec![s.t];
        row.extend(&s.q);
        if derivatives {
            row.extend(&s.qd);
            row.extend(&s.qdd);
        }
        row.extend(tau);
        let fields: Vec<String> = row.iter().map(f64::to_string).collect();
        let _ = writeln!(text, "{}", fields.join(","));
    }
    let path = scratch(name);
    std::fs::write(&path, text).expect("write csv");
    path.to_string_lossy().into_owned()
}

/// Normal deviates from a fixed seed (xorshift64, Box-Muller).
pub fn normal(seed: &mut u64) -> f64 {
    let mut uniform = || {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        ((*seed >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    let (u, v) = (uniform(), uniform());
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// Runs the `dynamics` binary of this package.
pub fn dynamics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(args)
        .output()
        .expect("run dynamics")
}

/// A successful run's JSON.
pub fn json(out: &Output) -> Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}
