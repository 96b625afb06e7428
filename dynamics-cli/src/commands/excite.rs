//! `dynamics excite ROBOT [--rotors] [--friction KINDS] [--period T] [--harmonics L]
//! [--periods N] [--rate HZ] [--q-min ..] [--q-max ..] [--qd-max ..] [--qdd-max ..] [--seed S]
//! [--evaluations N] [--set NAME=VALUE].. [--csv FILE] [--json]`: a periodic motion that excites
//! the robot's base parameters, for `dynamics identify`.
//!
//! Per joint, a finite Fourier series at rest at t = 0 (`excite::fourier`), scaled to the
//! largest motion within the joint's range, speed and acceleration limits; the coefficients
//! searched (random restarts, then a compass search: `excite::search`) to minimise the
//! condition number of the stacked base regressor `Y_B` over the period (`excite::condition`),
//! with the same base parameters and joint terms as `identify` (`--rotors`, `--friction`).
//!
//! The trajectory is written as `t,q1..qn,qd1..qdn,qdd1..qddn`, the derivatives exact (the
//! series' own), the file a controller replays and `identify` reads once the measured torques
//! are appended; the report gives the condition number reached, the limits and the method.

use super::values::settings;
use super::{load, robot_failure, usage, Failure};
use crate::args::{Excite, Numbers};
use crate::budget::{time_per_unit, Cost, Progress, BYTES_PER_NUMBER};
use crate::report::excite::Report;
use dynamics_codegen::model::JointKind;
use dynamics_codegen::pipeline::{self, Limit};
use dynamics_codegen::{Chain, Source};
use dynamics_identification::excite::design::{Problem, SEARCH_SAMPLES};
use dynamics_identification::excite::fourier::{Grid, Series};
use dynamics_identification::excite::limits::{joint_limits, Asked};
use dynamics_identification::{Error, Motion, Regressor};
use std::io::{BufWriter, Write};
use std::time::Instant;

/// The most samples of the regressor a run evaluates without `--no-limits`: those of the
/// search's evaluations and of the report's condition numbers.
const MAX_REGRESSOR_SAMPLES: f64 = 1e7;

pub fn run(args: &Excite) -> Result<String, Failure> {
    let started = Instant::now();
    let robot = load(&args.robot)?;
    let fields = settings("excite", &robot, &args.set)?;
    let joint_columns = args.joint_terms.columns(&robot);
    let regressor = Regressor::new(&robot, joint_columns, fields)
        .map_err(|e| robot_failure(&args.robot.path, e))?;
    let urdf = urdf_limits(args)?;
    let list = |o: &Option<Numbers>| o.as_ref().map(|Numbers(v)| v.clone());
    let lists = [&args.q_min, &args.q_max, &args.qd_max, &args.qdd_max].map(list);
    let asked: Asked = [0, 1, 2, 3].map(|k| lists[k].as_deref());
    let limits = joint_limits(&robot, urdf.as_deref(), asked).map_err(setting)?;
    let motion = Motion {
        period: args.period,
        harmonics: args.harmonics as usize,
        rate: args.rate,
    };
    let problem = motion
        .problem(&regressor, limits.iter().map(|l| l.limits).collect())
        .map_err(setting)?;
    let coordinates = robot.coordinates();
    check_cost(args, &problem, coordinates.len())?;
    let evaluations = args.evaluations as f64;
    let mut progress = Progress::new("dynamics excite", "evaluations", evaluations);
    let design = problem.design(args.seed, args.evaluations as usize, |done| {
        progress.update(done as f64);
    });
    if design.series.is_empty() {
        return Err(Failure::File(Error::NoMotion.to_string()));
    }
    write_trajectory(args.csv.as_deref(), &problem, &design.series, args.periods)?;
    // A row per coordinate: a mimic joint follows its joint, in its limits.
    let rows = coordinates
        .iter()
        .map(|&j| match robot.joints[j].kind {
            JointKind::Revolute => (j + 1, "rad"),
            JointKind::Prismatic => (j + 1, "m"),
        })
        .collect();
    let report = Report {
        robot: &robot.name,
        model: &regressor.joint_terms(),
        problem: &problem,
        limits: &limits,
        design: &design,
        periods: args.periods,
        seed: args.seed,
        rows,
        seconds: started.elapsed().as_secs_f64(),
    };
    let text = if args.json {
        report.json()
    } else {
        report.text()
    };
    if args.csv.is_some() {
        Ok(text)
    } else {
        // The trajectory took stdout.
        eprint!("{text}");
        Ok(String::new())
    }
}

/// An option's value refused.
fn setting(e: Error) -> Failure {
    usage("excite", &e.to_string())
}

/// The run's cost: the samples of the regressor its search and its report evaluate, and the
/// bytes of the trajectory of `joints` joints it writes.
fn check_cost(args: &Excite, problem: &Problem<'_>, joints: usize) -> Result<(), Failure> {
    let samples = problem.grid.samples() as f64;
    let evaluations = args.evaluations as f64;
    let per_evaluation = samples.min(SEARCH_SAMPLES as f64);
    let rows = args.periods as f64 * samples + 1.0;
    Cost {
        options: "--evaluations, --period × --rate, --periods",
        unit: format!(
            "samples of the regressor ({evaluations} evaluations of {per_evaluation} samples, \
             and the {samples} of a period twice for the report)"
        ),
        count: evaluations * per_evaluation + 2.0 * samples,
        limit: MAX_REGRESSOR_SAMPLES,
        bytes: rows * (1 + 3 * joints) as f64 * BYTES_PER_NUMBER,
    }
    .check(args.limits.no_limits, || {
        // One evaluation and a report over the fewest samples a period may have.
        let fewest = Motion::SAMPLES_PER_HARMONIC * problem.grid.harmonics;
        let small = Problem {
            grid: Grid::new(args.period, problem.grid.harmonics, fewest),
            limits: problem.limits.clone(),
            model: problem.model,
        };
        let time = time_per_unit(|| drop(small.design(args.seed, 1, |_| {})));
        time / (fewest.min(SEARCH_SAMPLES) + 2 * fewest) as f64
    })
    .map_err(|message| usage("excite", &message))
}

/// A URDF's `<limit>`s, per joint of the chain; `None` for a description file.
fn urdf_limits(args: &Excite) -> Result<Option<Vec<Limit>>, Failure> {
    let path = &args.robot.path;
    if !path.ends_with(".urdf") {
        return Ok(None);
    }
    let tips: Vec<&str> = args.robot.tips.iter().map(String::as_str).collect();
    let source = Source {
        path,
        chain: Chain {
            base: args.robot.base.as_deref(),
            tip: args.robot.tip.as_deref(),
            tips: &tips,
        },
        ..Source::default()
    };
    pipeline::joint_limits(&source).map(Some).map_err(|errors| {
        let lines: Vec<String> = errors.iter().map(ToString::to_string).collect();
        Failure::File(lines.join("\ndynamics: "))
    })
}

/// Writes `periods` periods of the motion, and the first sample of the next (at rest, where
/// the motion started), as `t,q..,qd..,qdd..` to `path`, or to stdout.
fn write_trajectory(
    path: Option<&str>,
    problem: &Problem,
    series: &[Series],
    periods: u64,
) -> Result<(), Failure> {
    let failed = |e: std::io::Error| Failure::File(format!("{}: {e}", path.unwrap_or("stdout")));
    let mut out: Box<dyn Write> = match path {
        Some(path) => Box::new(BufWriter::new(std::fs::File::create(path).map_err(failed)?)),
        None => Box::new(BufWriter::new(std::io::stdout().lock())),
    };
    let n = series.len();
    let header: Vec<String> = ["q", "qd", "qdd"]
        .iter()
        .flat_map(|g| (1..=n).map(move |i| format!("{g}{i}")))
        .collect();
    writeln!(out, "t,{}", header.join(",")).map_err(failed)?;
    let (m, period) = (problem.grid.samples(), problem.grid.period);
    let mut row = vec![0.0; 3 * n];
    // The cost's check bounded the rows.
    let last = periods as usize * m;
    let mut progress = Progress::new("dynamics excite", "rows written", last as f64);
    for k in 0..=last {
        progress.update(k as f64);
        // Whole periods exactly, then the steps within one: no drift over many periods.
        let t = (k / m) as f64 * period + (k % m) as f64 * period / m as f64;
        for (j, s) in problem.states(series, k).into_iter().enumerate() {
            (row[j], row[n + j], row[2 * n + j]) = (s.q, s.qd, s.qdd);
        }
        let values: Vec<String> = row.iter().map(f64::to_string).collect();
        writeln!(out, "{t},{}", values.join(",")).map_err(failed)?;
    }
    out.flush().map_err(failed)
}
