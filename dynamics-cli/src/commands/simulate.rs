//! `dynamics simulate ROBOT [--q0 ..] [--qd0 ..] [--tau ..] [--duration T] [--dt H]
//! [--set NAME=VALUE].. [--csv FILE] [--svg FILE]`: the motion under constant torques (from
//! many initial states with `--batch FILE`: [`super::simulate_batch`]).
//!
//! The state `x = (q, q̇)` follows `ẋ = (q̇, q̈)` with `M(q) q̈ = τ − C(q, q̇) q̇ − g(q) − τ_f(q̇)`
//! (springs in g, actuator inertia in M, friction as declared), solved through the LDLᵀ of M
//! ([`dynamics_codegen::Numeric::forward_dynamics`], run in f64), and is integrated by the
//! classical fourth-order Runge-Kutta method with a fixed step h:
//! `x' = x + h/6 (k₁ + 2k₂ + 2k₃ + k₄)`, `k₁ = f(x)`, `k₂ = f(x + h/2 k₁)`, `k₃ = f(x + h/2 k₂)`,
//! `k₄ = f(x + h k₃)`.

use super::values::{joints, numeric};
use super::{load, Failure};
use super::{usage, write_svg};
use crate::args::Simulate;
use crate::budget::{time_per_unit, Cost, Progress, BYTES_PER_NUMBER};
use crate::plot::{Envelope, Figure, Line, Panel};
use dynamics_codegen::Numeric;
use std::io::{BufWriter, Write};

/// The most steps a simulation takes without `--no-limits`.
const MAX_STEPS: f64 = 1e6;

/// Colors of the joints' lines.
const COLORS: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
];

pub fn run(args: &Simulate) -> Result<String, Failure> {
    if let Some(path) = &args.batch {
        return super::simulate_batch::run(args, path);
    }
    let robot = load(&args.robot)?;
    let numeric = numeric(&robot, "simulate", &args.set)?;
    let n = robot.joints.len();
    let mut q = joints("simulate", "--q0", args.q0.as_ref(), n)?;
    let mut qd = joints("simulate", "--qd0", args.qd0.as_ref(), n)?;
    let tau = joints("simulate", "--tau", args.tau.as_ref(), n)?;
    let steps = (args.duration / args.dt).round().max(1.0);
    Cost {
        options: "--duration / --dt",
        unit: "RK4 steps".into(),
        count: steps,
        limit: MAX_STEPS,
        // A line per step and the first: t, then q, q̇ and q̈.
        bytes: (steps + 1.0) * (1 + 3 * n) as f64 * BYTES_PER_NUMBER,
    }
    .check(args.limits.no_limits, || {
        time_per_unit(|| drop(rk4(&numeric, &q, &qd, &tau, args.dt)))
    })
    .map_err(|message| usage("simulate", &message))?;
    let (steps, h) = (steps as usize, args.duration / steps);
    let mut progress = Progress::new("dynamics simulate", "RK4 steps", steps as f64);
    let failed = |e: std::io::Error| {
        Failure::File(format!("{}: {e}", args.csv.as_deref().unwrap_or("stdout")))
    };
    // Rows are written as they are computed: nothing grows with the duration but the plot's
    // bounded envelope.
    let mut out: Box<dyn Write> = match &args.csv {
        Some(path) => Box::new(BufWriter::new(std::fs::File::create(path).map_err(failed)?)),
        None => Box::new(BufWriter::new(std::io::stdout().lock())),
    };
    let header: Vec<String> = ["q", "qd", "qdd"]
        .iter()
        .flat_map(|g| (1..=n).map(move |i| format!("{g}{i}")))
        .collect();
    writeln!(out, "t,{}", header.join(",")).map_err(failed)?;
    let mut envelope = Envelope::new(n + 3);
    let mut energy = (0.0, 0.0);
    for step in 0..=steps {
        let t = step as f64 * h;
        let qdd = acceleration(&numeric, &q, &qd, &tau).map_err(|e| at_time(args, t, &e))?;
        let (kinetic, potential) = numeric.energies(&q, &qd);
        let mut values = q.clone();
        values.extend([kinetic + potential, kinetic, potential]);
        envelope.push(t, &values);
        if step == 0 {
            energy.0 = kinetic + potential;
        }
        energy.1 = kinetic + potential;
        let row: Vec<String> = q
            .iter()
            .chain(&qd)
            .chain(&qdd)
            .map(f64::to_string)
            .collect();
        writeln!(out, "{t},{}", row.join(",")).map_err(failed)?;
        if step < steps {
            (q, qd) = rk4(&numeric, &q, &qd, &tau, h).map_err(|e| at_time(args, t, &e))?;
            progress.update(step as f64 + 1.0);
        }
    }
    out.flush().map_err(failed)?;
    if let Some(path) = &args.svg {
        write_svg(path, &figure(&robot.name, n, &envelope))?;
    }
    if args.csv.is_none() {
        return Ok(String::new());
    }
    let (first, last) = energy;
    Ok(format!(
        "{}: {steps} RK4 steps of {h} s to t = {} s; total energy {first:.6} J at the start, \
         {last:.6} J at the end (change {:.3e} J)\n",
        robot.name,
        args.duration,
        last - first
    ))
}

/// A failure of the motion at `t`, with the parameters `--set` gave, which may be its cause.
fn at_time(args: &Simulate, t: f64, message: &str) -> Failure {
    let sets: Vec<String> = args
        .set
        .iter()
        .map(|s| format!("{}={:?}", s.name, s.value))
        .collect();
    let with = if sets.is_empty() {
        String::new()
    } else {
        format!(" (with the parameters --set {})", sets.join(", "))
    };
    Failure::File(format!("at t = {t} s: {message}{with}"))
}

/// `q̈ = M⁻¹ (τ − C q̇ − g − τ_f)`, refused where `M(q)` is not positive definite or q̈ is not
/// finite.
fn acceleration(numeric: &Numeric, q: &[f64], qd: &[f64], tau: &[f64]) -> Result<Vec<f64>, String> {
    let qdd = numeric.forward_dynamics(q, qd, tau).map_err(|e| {
        format!(
            "M(q) is not positive definite (pivot {} of its LDLᵀ is {}) at q = {q:?}",
            e.pivot + 1,
            e.value
        )
    })?;
    if qdd.iter().all(|x| x.is_finite()) {
        Ok(qdd)
    } else {
        Err(format!(
            "the motion diverges: q̈ is not a finite number at q = {q:?}, q̇ = {qd:?}"
        ))
    }
}

/// One step of the classical Runge-Kutta method.
fn rk4(
    numeric: &Numeric,
    q: &[f64],
    qd: &[f64],
    tau: &[f64],
    h: f64,
) -> Result<(Vec<f64>, Vec<f64>), String> {
    let shifted = |x: &[f64], dx: &[f64], k: f64| -> Vec<f64> {
        x.iter().zip(dx).map(|(a, b)| a + k * b).collect()
    };
    let k1 = (qd.to_vec(), acceleration(numeric, q, qd, tau)?);
    let (q2, qd2) = (shifted(q, &k1.0, h / 2.0), shifted(qd, &k1.1, h / 2.0));
    let k2 = (qd2.clone(), acceleration(numeric, &q2, &qd2, tau)?);
    let (q3, qd3) = (shifted(q, &k2.0, h / 2.0), shifted(qd, &k2.1, h / 2.0));
    let k3 = (qd3.clone(), acceleration(numeric, &q3, &qd3, tau)?);
    let (q4, qd4) = (shifted(q, &k3.0, h), shifted(qd, &k3.1, h));
    let k4 = (qd4.clone(), acceleration(numeric, &q4, &qd4, tau)?);
    let combine = |x: &[f64], a: &[f64], b: &[f64], c: &[f64], d: &[f64]| -> Vec<f64> {
        (0..x.len())
            .map(|i| x[i] + h / 6.0 * (a[i] + 2.0 * b[i] + 2.0 * c[i] + d[i]))
            .collect()
    };
    Ok((
        combine(q, &k1.0, &k2.0, &k3.0, &k4.0),
        combine(qd, &k1.1, &k2.1, &k3.1, &k4.1),
    ))
}

fn figure<'e>(name: &str, n: usize, envelope: &'e Envelope) -> Figure<'e> {
    let color = |j: usize| COLORS[j % COLORS.len()];
    let joints = (0..n)
        .map(|j| Line {
            label: format!("q{}", j + 1),
            color: color(j),
            series: j,
            bold: false,
        })
        .collect();
    let energy = [
        ("total", "#000000"),
        ("kinetic", "#d62728"),
        ("potential", "#2ca02c"),
    ];
    let mut legend: Vec<(String, &'static str)> =
        (0..n).map(|j| (format!("q{}", j + 1), color(j))).collect();
    legend.extend(energy.iter().map(|(l, c)| (format!("{l} energy"), *c)));
    Figure {
        title: format!("{name}: simulated motion (RK4)"),
        legend,
        rows: vec![
            vec![Panel {
                title: "joint positions (rad or m)".into(),
                lines: joints,
            }],
            vec![Panel {
                title: "energy (J)".into(),
                lines: energy
                    .iter()
                    .enumerate()
                    .map(|(k, (label, color))| Line {
                        label: (*label).to_string(),
                        color,
                        series: n + k,
                        bold: k == 0,
                    })
                    .collect(),
            }],
        ],
        widths: vec![760.0],
        envelope,
    }
}
