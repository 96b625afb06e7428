//! `dynamics size` and `dynamics simulate` end to end, on a pendulum whose equations are known
//! by hand: a point mass m at distance l from a revolute joint (gravity −g y, q = 0
//! horizontal), with actuator inertia I_a and viscous friction b:
//! `τ = m l² q̈ + I_a q̈ + m g l cos q + b q̇`. Also the CSV errors, named by line and column.

use crate::runner::dynamics;
use serde_json::Value;
use std::path::PathBuf;
use std::process::Output;

const M: f64 = 2.0;
const L: f64 = 0.5;
const G: f64 = 9.81;
const IA: f64 = 0.03;
const B: f64 = 0.4;

/// A scratch directory of this test binary.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_trajectory");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name)
}

/// The pendulum's description, in a file of the calling test's own (tests run in parallel).
fn pendulum(test: &str, friction: bool) -> String {
    let path = scratch(&format!("{test}.toml"));
    let extra = if friction {
        format!("actuator_inertia = {IA}\nfriction_viscous = {B}\n")
    } else {
        String::new()
    };
    let text = format!(
        "name = \"pendulum\"\ngravity = [0, -{G}, 0]\n[[joints]]\ntype = \"revolute\"\n\
         a = {L}\nmass = {M}\n{extra}"
    );
    std::fs::write(&path, text).expect("write robot");
    path.to_string_lossy().into_owned()
}

fn json(out: &Output) -> Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * (1.0 + b.abs())
}

#[test]
fn a_pendulum_held_horizontal_needs_m_g_l() {
    let csv = scratch("static.csv");
    std::fs::write(&csv, "t,q1,qd1,qdd1\n0,0,0,0\n1,0,0,0\n").unwrap();
    let report = json(&dynamics(&[
        "size",
        &pendulum("static", false),
        "--csv",
        csv.to_str().unwrap(),
        "--json",
    ]));
    let joint = &report["joints"][0];
    assert!(close(joint["peak"].as_f64().unwrap(), M * G * L, 1e-12));
    assert!(close(joint["rms"].as_f64().unwrap(), M * G * L, 1e-12));
    assert!(close(
        joint["terms_at_peak"]["gravity"].as_f64().unwrap(),
        M * G * L,
        1e-12
    ));
    assert_eq!(joint["peak_power"].as_f64(), Some(0.0));
    assert_eq!(report["samples"].as_u64(), Some(2));
}

/// τ and q̇ of the quintic move from 0 to `to` in `duration`, by hand.
fn by_hand(to: f64, duration: f64, t: f64) -> (f64, f64, [f64; 4]) {
    let s = t / duration;
    let q = to * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
    let qd = to * 30.0 * s * s * (1.0 - s) * (1.0 - s) / duration;
    let qdd = to * 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s) / (duration * duration);
    let terms = [M * L * L * qdd, M * G * L * q.cos(), IA * qdd, B * qd];
    (terms.iter().sum(), qd, terms)
}

/// Peak, RMS (trapezoidal rule over time) and peak power of `samples` samples of the move.
fn expected(to: f64, duration: f64, samples: usize) -> (f64, f64, f64, [f64; 4]) {
    let (mut peak, mut power, mut integral, mut at_peak) = (0.0f64, 0.0f64, 0.0, [0.0; 4]);
    let mut previous: Option<(f64, f64)> = None;
    for k in 0..samples {
        let t = duration * k as f64 / (samples - 1) as f64;
        let (tau, qd, terms) = by_hand(to, duration, t);
        if tau.abs() > peak.abs() {
            (peak, at_peak) = (tau, terms);
        }
        if (tau * qd).abs() > power.abs() {
            power = tau * qd;
        }
        if let Some((t0, s0)) = previous {
            integral += 0.5 * (s0 + tau * tau) * (t - t0);
        }
        previous = Some((t, tau * tau));
    }
    (peak, (integral / duration).sqrt(), power, at_peak)
}

#[test]
fn the_quintic_move_of_a_pendulum_with_friction_and_actuator_inertia() {
    let out = dynamics(&[
        "size",
        &pendulum("quintic", true),
        "--from",
        "0",
        "--to",
        "1.2",
        "--duration",
        "0.8",
        "--samples",
        "801",
        "--json",
    ]);
    let joint = json(&out)["joints"][0].clone();
    let (peak, rms, power, terms) = expected(1.2, 0.8, 801);
    assert!(
        close(joint["peak"].as_f64().unwrap(), peak, 1e-12),
        "{joint}"
    );
    assert!(close(joint["rms"].as_f64().unwrap(), rms, 1e-12), "{joint}");
    assert!(close(joint["peak_power"].as_f64().unwrap(), power, 1e-12));
    let got = &joint["terms_at_peak"];
    for (name, want) in ["inertial", "gravity", "actuator", "friction"]
        .iter()
        .zip(terms)
    {
        assert!(
            close(got[name].as_f64().unwrap(), want, 1e-12),
            "{name}: {got}"
        );
    }
    assert_eq!(got["coriolis"].as_f64(), Some(0.0));
}

#[test]
fn positions_only_are_differentiated_and_long_files_report_progress() {
    // 40,001 samples of the move, q only: q̇ and q̈ by central differences (error O(h²)).
    let (to, duration, samples) = (1.2, 0.8, 40_001);
    let mut text = String::from("t,q1\n");
    for k in 0..samples {
        let t = duration * k as f64 / (samples - 1) as f64;
        let s = t / duration;
        let q = to * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
        text += &format!("{t:.17e},{q:.17e}\n");
    }
    let csv = scratch("positions.csv");
    std::fs::write(&csv, text).unwrap();
    let out = dynamics(&[
        "size",
        &pendulum("positions", true),
        "--csv",
        csv.to_str().unwrap(),
        "--json",
    ]);
    let joint = json(&out)["joints"][0].clone();
    let (peak, rms, _, _) = expected(to, duration, samples);
    assert!(
        close(joint["peak"].as_f64().unwrap(), peak, 1e-6),
        "{joint} {peak}"
    );
    assert!(
        close(joint["rms"].as_f64().unwrap(), rms, 1e-6),
        "{joint} {rms}"
    );
    let progress = String::from_utf8_lossy(&out.stderr);
    assert!(progress.contains("50%"), "{progress}");
}

#[test]
fn the_svg_is_written_and_small() {
    let svg = scratch("pendulum.svg");
    let out = dynamics(&[
        "size",
        &pendulum("svg", true),
        "--from",
        "0",
        "--to",
        "1",
        "--samples",
        "100000",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    for label in ["inertial", "gravity", "actuator", "friction", "power"] {
        assert!(text.contains(label), "{label}");
    }
    assert!(text.len() < 60_000, "{}", text.len());
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(
        table.starts_with("pendulum: 100000 samples, t = 0 to 2 s"),
        "{table}"
    );
}

#[test]
fn csv_errors_name_the_line_and_column() {
    let robot = pendulum("errors", false);
    let cases = [
        (
            "t,q1\n0,0\n1,0,2\n",
            "line 3, column 3: 3 values; the header has 2 columns",
        ),
        (
            "t,q1\n0,0\n\n1,abc\n",
            "line 4, column 2 (q1): `abc` is not a number",
        ),
        (
            "t,q1\n0,0\n1,0\n0.5,0\n",
            "line 4, column 1 (t): time does not increase: 0.5 after 1",
        ),
        (
            "# c\nt,q1\n0,NaN\n",
            "line 3, column 2 (q1): `NaN` is not a finite number",
        ),
        (
            "t,q1,q2,q3,q4\n0,0,0,0,0\n",
            "line 1: the header has 5 columns; the robot has 1 joints",
        ),
        (
            "t,qd1\n",
            "line 1, column 2 (qd1): expected the header name `q1`",
        ),
        (
            "t,q1\n0,0\n1,0\n",
            "line 3: 2 samples: estimating q̇ and q̈ takes at least 3",
        ),
    ];
    for (k, (text, message)) in cases.iter().enumerate() {
        let csv = scratch(&format!("bad{k}.csv"));
        std::fs::write(&csv, text).unwrap();
        let out = dynamics(&["size", &robot, "--csv", csv.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(1), "{text}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        let want = format!("dynamics: {}: {message}", csv.display());
        assert!(stderr.starts_with(&want), "{stderr}\nwant: {want}");
    }
}

#[test]
fn usage_errors() {
    let robot = pendulum("usage", false);
    for args in [
        vec!["size", &robot],
        vec!["size", &robot, "--from", "0,1", "--to", "1,1"],
        vec![
            "size",
            &robot,
            "--from",
            "0",
            "--to",
            "1",
            "--duration",
            "0",
        ],
        vec!["simulate", &robot, "--q0", "1,2"],
    ] {
        let out = dynamics(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
}

/// The complete elliptic integral of the first kind, K(k), by the arithmetic-geometric mean.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-15 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// `simulate` on the pendulum from rest at `q0`: the summary's energy at the start, at the end
/// and its change, and the CSV rows (t, q, q̇, q̈).
fn simulate(
    test: &str,
    friction: bool,
    q0: f64,
    duration: &str,
    dt: &str,
) -> ([f64; 3], Vec<Vec<f64>>) {
    let csv = scratch(&format!("{test}.csv"));
    let out = dynamics(&[
        "simulate",
        &pendulum(test, friction),
        "--q0",
        &q0.to_string(),
        "--duration",
        duration,
        "--dt",
        dt,
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8(out.stdout).unwrap();
    let energy = |after: &str| -> f64 {
        let rest = summary.split(after).nth(1).expect(&summary);
        rest.trim_start()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .expect(&summary)
    };
    let rows = std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let change = energy("(change");
    (
        [energy("total energy"), energy("J at the start,"), change],
        rows,
    )
}

#[test]
fn a_simulated_pendulum_keeps_its_energy_and_swings_with_its_period() {
    // Released at rest 1 rad from hanging (q = −π/2): the period is 4 √(l/g) K(sin ½).
    let amplitude: f64 = 1.0;
    let period = 4.0 * (L / G).sqrt() * elliptic_k((amplitude / 2.0).sin());
    let q0 = -std::f64::consts::FRAC_PI_2 + amplitude;
    let ([.., change], rows) = simulate("swing", false, q0, "3", "0.001");
    assert!(change.abs() < 1e-8, "{change}");
    // Turning points: q̇ changes sign; interpolated linearly between the samples.
    let turns: Vec<f64> = rows
        .windows(2)
        .filter(|w| w[0][2] * w[1][2] < 0.0)
        .map(|w| w[0][0] + (w[1][0] - w[0][0]) * w[0][2] / (w[0][2] - w[1][2]))
        .collect();
    assert!(turns.len() >= 3, "{turns:?}");
    for pair in turns.windows(2) {
        assert!(
            close(pair[1] - pair[0], period / 2.0, 1e-5),
            "{turns:?} vs {period}"
        );
    }
}

#[test]
fn viscous_friction_dissipates_the_energy_lost_in_a_simulation() {
    // E(0) − E(T) = ∫ b q̇² dt (actuator inertia in the kinetic energy, no torque applied).
    let ([start, end, _], rows) = simulate("damped", true, 0.3, "1.5", "0.0005");
    let dissipated: f64 = rows
        .windows(2)
        .map(|w| 0.5 * B * (w[0][2] * w[0][2] + w[1][2] * w[1][2]) * (w[1][0] - w[0][0]))
        .sum();
    assert!(dissipated > 0.1, "{dissipated}");
    assert!(
        (start - end - dissipated).abs() < 1e-5,
        "{start} − {end} vs {dissipated}"
    );
}

/// The last row (t, q, q̇, q̈) of `simulate` from `(q0, qd0)` alone, over 0.5 s.
fn last_row_alone(robot: &str, k: usize, q0: f64, qd0: f64) -> Vec<f64> {
    let csv = scratch(&format!("batch_alone_{k}.csv"));
    let alone = dynamics(&[
        "simulate",
        robot,
        "--q0",
        &q0.to_string(),
        "--qd0",
        &qd0.to_string(),
        "--duration",
        "0.5",
        "--dt",
        "0.001",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(alone.status.success());
    std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect()
}

#[test]
fn a_batch_of_initial_states_ends_where_each_alone_ends() {
    // Five states (a partial group of lanes), q̇ given, friction and actuator inertia on.
    let states: [(f64, f64); 5] = [
        (0.3, 0.0),
        (-1.2, 0.5),
        (0.9, -2.0),
        (2.5, 1.0),
        (-0.4, 3.0),
    ];
    let file = scratch("batch_states.csv");
    let lines: Vec<String> = states
        .iter()
        .enumerate()
        .map(|(k, (q, qd))| format!("{k},{q},{qd}"))
        .collect();
    std::fs::write(&file, format!("t,q1,qd1\n{}\n", lines.join("\n"))).unwrap();
    let robot = pendulum("batch", true);
    let out = dynamics(&[
        "simulate",
        &robot,
        "--batch",
        file.to_str().unwrap(),
        "--duration",
        "0.5",
        "--dt",
        "0.001",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(
        text.lines().next(),
        Some("t0,q1,qd1,energy_start,energy_end")
    );
    assert_eq!(rows.len(), states.len());
    for (k, (q0, qd0)) in states.iter().enumerate() {
        let last = last_row_alone(&robot, k, *q0, *qd0);
        // t, q, q̇, q̈ of the last step against t0, q, q̇, energies.
        assert_eq!(rows[k][0], k as f64);
        assert!(
            close(rows[k][1], last[1], 1e-9),
            "state {k}: {:?} vs {last:?}",
            rows[k]
        );
        assert!(
            close(rows[k][2], last[2], 1e-9),
            "state {k}: {:?} vs {last:?}",
            rows[k]
        );
        // The energy at the start by hand; friction only takes energy away.
        let by_hand = 0.5 * (M * L * L + IA) * qd0 * qd0 + M * G * L * q0.sin();
        assert!(
            close(rows[k][3], by_hand, 1e-12),
            "state {k}: {:?}",
            rows[k]
        );
        assert!(rows[k][4] < rows[k][3], "state {k}: {:?}", rows[k]);
    }
}
