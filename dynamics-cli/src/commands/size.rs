//! `dynamics size ROBOT (--csv FILE | --from Q --to Q [--duration T] [--samples N])
//! [--set NAME=VALUE].. [--svg FILE] [--json]`: actuator sizing along a trajectory
//! ([`dynamics_identification::sizing`], its figure [`crate::report::sizing`]), read as a stream ([`dynamics_identification::trajectory`]).

use super::values::{joints, settings};
use super::{load, Failure};
use super::{usage, write_svg};
use crate::args::Size;
use crate::budget::{time_per_unit, Cost, Progress};
use crate::format::unsigned_zero;
use crate::plot::{self, Envelope};
use crate::report::sizing::figure;
use dynamics_codegen::model::JointKind;
use dynamics_identification::sizing::terms::TermsTape;
use dynamics_identification::sizing::{unit, Sizer, SERIES, TERMS};
use dynamics_identification::trajectory;
use serde_json::json;
use std::fmt::Write as _;
use std::io::BufReader;

/// Files from this size on report their progress on stderr.
const LONG_INPUT: u64 = 1 << 20;

/// The most samples of a move `size` takes without `--no-limits`.
const MAX_SAMPLES: f64 = 1e7;

pub fn run(args: &Size) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = dynamics_codegen::derive(&robot);
    let fields = settings("size", &robot, &args.set)?;
    let mut terms = TermsTape::new(&robot, &eq, &fields).map_err(Failure::File)?;
    let n = robot.joints.len();
    let kinds: Vec<JointKind> = robot.joints.iter().map(|j| j.kind).collect();
    let envelope = args.svg.is_some().then(|| Envelope::new(SERIES * n));
    let mut sizer = Sizer::new(&mut terms, n, envelope);
    let source = if let Some(path) = &args.csv {
        let method = read(path, n, &mut sizer)?;
        format!("{path}, {method}")
    } else {
        let from = joints("size", "--from", args.from.as_ref(), n)?;
        let to = joints("size", "--to", args.to.as_ref(), n)?;
        check_move(&from, &to, args.duration)?;
        let samples = args.samples as f64;
        Cost {
            options: "--samples",
            unit: "samples of the move".into(),
            count: samples,
            limit: MAX_SAMPLES,
            bytes: 0.0,
        }
        .check(args.limits.no_limits, || {
            let few = 64;
            let time = time_per_unit(|| {
                trajectory::quintic(&from, &to, args.duration, few, |s| sizer.push(s));
            });
            time / few as f64
        })
        .map_err(|message| usage("size", &message))?;
        let mut progress = Progress::new("dynamics size", "samples", samples);
        let mut done = 0.0;
        trajectory::quintic(&from, &to, args.duration, args.samples as usize, |s| {
            sizer.push(s);
            done += 1.0;
            progress.update(done);
        });
        "quintic move, exact q̇ and q̈".to_string()
    };
    sizer.finish();
    if let Some((line, t, (column, name, value))) = &sizer.non_finite {
        let t = trajectory::decimal(*t);
        let with_set = if args.set.is_empty() {
            ""
        } else {
            " (with --set's parameters)"
        };
        return Err(Failure::File(match &args.csv {
            Some(path) => format!(
                "{path}{with_set}: line {line}, column {column} ({name}): at t = {t} s τ² or the \
                 power τ q̇ is not a finite number; the sample's largest value is {value:e}, of \
                 this column (or of its differences)"
            ),
            None => format!(
                "--from, --to, --duration{with_set}: at t = {t} s τ² or the power τ q̇ is not a \
                 finite number (the sample's largest value is {name} = {value:e}): expected a \
                 motion whose q̇ and q̈ the robot's torques can follow"
            ),
        }));
    }
    if let (Some(path), Some(envelope)) = (&args.svg, &sizer.series) {
        let title = format!("{}: joint torques and power ({source})", robot.name);
        write_svg(path, &figure(title, &kinds, envelope))?;
    }
    Ok(if args.json {
        json_report(&robot.name, &source, &kinds, &sizer)
    } else {
        table(&robot.name, &source, &kinds, &sizer)
    })
}

/// A quintic move whose acceleration is a finite number, largest `10/√3 · |Δq| / T²`.
fn check_move(from: &[f64], to: &[f64], duration: f64) -> Result<(), Failure> {
    let largest = from
        .iter()
        .zip(to)
        .map(|(a, b)| (b - a).abs())
        .fold(0.0, f64::max);
    let peak = 10.0 / 3.0_f64.sqrt() * largest / (duration * duration);
    if largest.is_finite() && peak.is_finite() && duration * duration > 0.0 {
        return Ok(());
    }
    Err(usage(
        "size",
        &format!(
            "--from, --to, --duration: a move of {largest:?} (rad or m) in {duration:?} s \
             accelerates up to 10/√3 · |Δq| / T² = {peak:?}: expected a finite number (a \
             longer --duration or a shorter move)"
        ),
    ))
}

/// Streams the CSV file at `path` into `sizer`, with progress on stderr for a long file.
/// How q̇ and q̈ were had.
fn read(
    path: &str,
    n: usize,
    sizer: &mut Sizer<'_, Option<Envelope>>,
) -> Result<&'static str, Failure> {
    let file = std::fs::File::open(path).map_err(|e| Failure::File(format!("{path}: {e}")))?;
    let total = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut reported = 0;
    let progress = |bytes: u64| {
        let percent = bytes * 100 / total.max(1);
        if total >= LONG_INPUT && percent >= reported + 10 {
            reported = percent / 10 * 10;
            eprintln!("dynamics size: {path}: {reported}%");
        }
    };
    let columns = trajectory::Columns {
        joints: n,
        torques: false,
        base: Default::default(),
    };
    trajectory::read_csv(BufReader::new(file), columns, |s| sizer.push(s), progress)
        .map(|(_, method)| method)
        .map_err(|e| Failure::File(format!("{path}: {e}")))
}

/// The report as aligned columns; the terms as shares of τ at its peak (signed, summing to
/// 100 %).
fn table(
    name: &str,
    source: &str,
    kinds: &[JointKind],
    sizer: &Sizer<'_, Option<Envelope>>,
) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{name}: {} samples, t = {} to {} s ({source})",
        sizer.samples, sizer.start, sizer.end
    );
    let _ = writeln!(
        out,
        "{:>5} {:>13} {:>9} {:>13} {:>12} {:>9} | share of τ at its peak: {}",
        "joint",
        "peak τ",
        "at t (s)",
        "RMS τ",
        "peak power",
        "at t (s)",
        TERMS.join(", ")
    );
    for (j, (r, &kind)) in sizer.joints.iter().zip(kinds).enumerate() {
        let unit = unit(kind);
        let shares: Vec<String> = r
            .terms_at_peak
            .iter()
            .map(|x| format!("{:>9}", share(*x, &r.terms_at_peak)))
            .collect();
        let _ = writeln!(
            out,
            "{:>5} {:>9} {unit:<3} {:>9} {:>9} {unit:<3} {:>10} W {:>9} | {}",
            j + 1,
            plot::number(r.peak),
            plot::number(r.peak_time),
            plot::number(r.rms),
            plot::number(r.peak_power),
            plot::number(r.peak_power_time),
            shares.join(" ")
        );
    }
    out
}

/// `term` as a percentage of the sum of `terms`, unless that sum is only round-off.
fn share(term: f64, terms: &[f64; 5]) -> String {
    let total: f64 = terms.iter().sum();
    let scale: f64 = terms.iter().map(|x| x.abs()).sum();
    if total.abs() <= 1e-9 * scale || total == 0.0 {
        "-".into()
    } else {
        format!("{:.1} %", unsigned_zero(100.0 * term / total))
    }
}

fn json_report(
    name: &str,
    source: &str,
    kinds: &[JointKind],
    sizer: &Sizer<'_, Option<Envelope>>,
) -> String {
    let joints: Vec<serde_json::Value> = sizer
        .joints
        .iter()
        .zip(kinds)
        .map(|(r, &kind)| {
            let terms: serde_json::Map<String, serde_json::Value> = TERMS
                .iter()
                .zip(r.terms_at_peak)
                .map(|(name, x)| ((*name).to_string(), json!(unsigned_zero(x))))
                .collect();
            json!({
                "unit": unit(kind),
                "peak": unsigned_zero(r.peak),
                "peak_time": r.peak_time,
                "rms": r.rms,
                "peak_power": unsigned_zero(r.peak_power),
                "peak_power_time": r.peak_power_time,
                "terms_at_peak": terms,
            })
        })
        .collect();
    let report = json!({
        "robot": name,
        "source": source,
        "samples": sizer.samples,
        "start": sizer.start,
        "end": sizer.end,
        "joints": joints,
    });
    format!("{report:#}\n")
}
