//! `dynamics simulate ROBOT --batch FILE [--tau ..] [--duration T] [--dt H] [--csv OUT]`: the
//! motion from many initial states at once, each integrated as `simulate` integrates one (RK4,
//! fixed step, constant torques), four states at a time in vector lanes.
//!
//! The initial states are the lines of a trajectory file, in the format `size --csv` reads
//! (`t,q1..qn`, optionally `qd1..qdn`, `qdd1..qddn`, `t` increasing): every line's `(q, q̇)` is
//! one initial state, `q̇ = 0` in a file of positions only. The output has a line per state:
//! its time in the file, the state at the end of the duration, and the total energy at the
//! start and at the end. The file is read twice, to count and check its states and then to
//! simulate them four by four, each group's lines written when it is done: nothing held grows
//! with the file.
//!
//! A group costs one state's steps whether it holds one state or four: the limit without
//! `--no-limits` counts steps of a group ([`MAX_GROUP_STEPS`]), and the output's bytes.
//!
//! `q̈` is the forward dynamics' closed form, the same graph the generated `forward_dynamics`
//! is emitted from (LDLᵀ of M unrolled), evaluated by a tape in the runtime's `F64x4`
//! (`joint_tape`); a state whose mass matrix stops being positive definite, or whose motion
//! diverges, ends with non-finite values, reported as such.

use super::usage;
use super::values::{joints, settings};
use super::{load, Failure};
use crate::args::Simulate;
use crate::budget::{time_per_unit, Cost, Progress, BYTES_PER_NUMBER};
use dynamics_codegen::pipeline::TapeScalar;
use dynamics_identification::joint_tape::{gather, JointTape, Work};
use dynamics_identification::lanes::{Four, LANES};
use dynamics_identification::trajectory::{self, Given, Sample};
use std::io::{BufReader, BufWriter, Write};

/// The most RK4 steps of a group of [`LANES`] states a batch takes without `--no-limits`: a
/// group costs one state's steps, whether it holds one state or four.
const MAX_GROUP_STEPS: f64 = 1e6;

/// One robot's forward dynamics and energies, as tapes.
struct Dynamics {
    forward: JointTape,
    energy: JointTape,
    n: usize,
}

/// Where the lines go, and what came of the groups so far.
struct Output<'a> {
    out: Box<dyn Write + 'a>,
    path: &'a str,
    steps: usize,
    h: f64,
    diverged: usize,
    done: f64,
    progress: Progress,
}

pub fn run(args: &Simulate, path: &str) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let n = robot.joints.len();
    let tau = joints("simulate", "--tau", args.tau.as_ref(), n)?;
    let eq = dynamics_codegen::derive(&robot);
    let fields = settings("simulate", &robot, &args.set)?;
    let tape = |outputs: &[_]| {
        JointTape::new(&eq.graph, outputs, &eq.angle_offsets, &fields, Some(&tau))
            .map_err(Failure::File)
    };
    let dynamics = Dynamics {
        forward: tape(&eq.forward.qdd)?,
        energy: tape(&[eq.kinetic_energy, eq.potential_energy])?,
        n,
    };
    // A first pass checks every line and counts the states, which are then streamed: nothing
    // held grows with the file.
    let states = read(path, n, |_| {})?;
    let steps = (args.duration / args.dt).round().max(1.0);
    let groups = states.div_ceil(LANES);
    Cost {
        options: "--batch, --duration / --dt",
        unit: format!(
            "RK4 steps of a group ({states} states in {groups} group{} of up to {LANES}, \
             {steps} steps each)",
            if groups == 1 { "" } else { "s" }
        ),
        count: groups as f64 * steps,
        limit: MAX_GROUP_STEPS,
        bytes: states as f64 * (3 + 2 * n) as f64 * BYTES_PER_NUMBER,
    }
    .check(args.limits.no_limits, || {
        let zero = vec![Four::splat(0.0); n];
        let mut work = Work::default();
        time_per_unit(|| drop(dynamics.rk4(&zero, &zero, args.dt, &mut work)))
    })
    .map_err(|message| usage("simulate", &message))?;
    let (steps, h) = (steps as usize, args.duration / steps);
    let target = args.csv.as_deref().unwrap_or("stdout");
    let failed = |e: std::io::Error| Failure::File(format!("{target}: {e}"));
    let out: Box<dyn Write> = match &args.csv {
        Some(out) => Box::new(BufWriter::new(std::fs::File::create(out).map_err(failed)?)),
        None => Box::new(BufWriter::new(std::io::stdout().lock())),
    };
    let mut output = Output {
        out,
        path: target,
        steps,
        h,
        diverged: 0,
        done: 0.0,
        progress: Progress::new(
            "dynamics simulate --batch",
            "RK4 steps of a group",
            groups as f64 * steps as f64,
        ),
    };
    writeln!(output.out, "{}", header(n)).map_err(failed)?;
    let mut group = Vec::with_capacity(LANES);
    let mut written = Ok(());
    read(path, n, |state| {
        if written.is_ok() {
            group.push(state);
        }
        if group.len() == LANES {
            written = dynamics.write(&group, &mut output);
            group.clear();
        }
    })?;
    if !group.is_empty() && written.is_ok() {
        written = dynamics.write(&group, &mut output);
    }
    written?;
    output.out.flush().map_err(failed)?;
    if args.csv.is_none() {
        return Ok(String::new());
    }
    Ok(format!(
        "{}: {states} initial states from {path}, each {steps} RK4 steps of {h} s to t = {} s, \
         {LANES} at a time; {} diverged (non-finite at the end)\n",
        robot.name, args.duration, output.diverged
    ))
}

/// Passes the initial states of the file at `path` to `each`, in order: each line's `t`, `q`
/// and `q̇` (zero where the file gives positions only); how many.
fn read(path: &str, n: usize, mut each: impl FnMut(Sample)) -> Result<usize, Failure> {
    let file = std::fs::File::open(path).map_err(|e| Failure::File(format!("{path}: {e}")))?;
    let columns = trajectory::Columns {
        joints: n,
        torques: false,
        base: Default::default(),
    };
    let mut count = 0;
    trajectory::read_rows(
        BufReader::new(file),
        columns,
        |line, given, row| {
            let qd = match given {
                Given::Positions => vec![0.0; n],
                Given::Velocities | Given::Accelerations => row[1 + n..1 + 2 * n].to_vec(),
            };
            count += 1;
            each(Sample {
                t: row[0],
                q: row[1..=n].to_vec(),
                qd,
                qdd: Vec::new(),
                tau: Vec::new(),
                line,
                given,
            });
            Ok(())
        },
        |_| {},
    )
    .map_err(|e| Failure::File(format!("{path}: {e}")))?;
    Ok(count)
}

/// The output's header: the state's time in the file, the final state, the energies.
fn header(n: usize) -> String {
    let joints = |g: &'static str| (1..=n).map(move |i| format!("{g}{i}"));
    let names: Vec<String> = std::iter::once("t0".to_string())
        .chain(joints("q"))
        .chain(joints("qd"))
        .chain(["energy_start".to_string(), "energy_end".to_string()])
        .collect();
    names.join(",")
}

impl Dynamics {
    /// Simulates the states of `group` (up to [`LANES`]) and writes their lines.
    fn write(&self, group: &[Sample], output: &mut Output<'_>) -> Result<(), Failure> {
        let ends = self.simulate(group, output);
        for (s, end) in group.iter().zip(ends) {
            output.diverged += usize::from(!end.iter().all(|x| x.is_finite()));
            let values: Vec<String> = end.iter().map(f64::to_string).collect();
            writeln!(output.out, "{},{}", s.t, values.join(","))
                .map_err(|e| Failure::File(format!("{}: {e}", output.path)))?;
        }
        Ok(())
    }

    /// The final `(q, q̇)` and the total energy at the start and at the end, of each of up to
    /// [`LANES`] initial states.
    fn simulate(&self, group: &[Sample], output: &mut Output<'_>) -> Vec<Vec<f64>> {
        let lanes = |x: fn(&Sample) -> &[f64]| -> Vec<Four> {
            let values: Vec<&[f64]> = group.iter().map(x).collect();
            (0..self.n).map(|j| gather(&values, j)).collect()
        };
        let (mut q, mut qd) = (lanes(|s| &s.q), lanes(|s| &s.qd));
        let mut work = Work::default();
        let start = self.energy(&q, &qd, &mut work);
        for _ in 0..output.steps {
            (q, qd) = self.rk4(&q, &qd, output.h, &mut work);
            output.done += 1.0;
            output.progress.update(output.done);
        }
        let end = self.energy(&q, &qd, &mut work);
        (0..group.len())
            .map(|l| {
                let lane = |x: &Four| x.lanes()[l];
                q.iter()
                    .chain(&qd)
                    .map(lane)
                    .chain([lane(&start), lane(&end)])
                    .collect()
            })
            .collect()
    }

    /// `q̈` at `(q, q̇)`.
    fn acceleration(&self, q: &[Four], qd: &[Four], work: &mut Work) -> Vec<Four> {
        let mut qdd = vec![Four::splat(0.0); self.n];
        self.forward.eval(q, qd, &[], work, &mut qdd);
        qdd
    }

    /// Kinetic plus potential energy.
    fn energy(&self, q: &[Four], qd: &[Four], work: &mut Work) -> Four {
        let mut e = [Four::splat(0.0); 2];
        self.energy.eval(q, qd, &[], work, &mut e);
        e[0] + e[1]
    }

    /// One step of the classical Runge-Kutta method, as `simulate`'s.
    fn rk4(&self, q: &[Four], qd: &[Four], h: f64, work: &mut Work) -> (Vec<Four>, Vec<Four>) {
        let shifted = |x: &[Four], dx: &[Four], k: f64| -> Vec<Four> {
            x.iter()
                .zip(dx)
                .map(|(&a, &b)| a + Four::splat(k) * b)
                .collect()
        };
        let k1 = (qd.to_vec(), self.acceleration(q, qd, work));
        let (q2, qd2) = (shifted(q, &k1.0, h / 2.0), shifted(qd, &k1.1, h / 2.0));
        let k2 = (qd2.clone(), self.acceleration(&q2, &qd2, work));
        let (q3, qd3) = (shifted(q, &k2.0, h / 2.0), shifted(qd, &k2.1, h / 2.0));
        let k3 = (qd3.clone(), self.acceleration(&q3, &qd3, work));
        let (q4, qd4) = (shifted(q, &k3.0, h), shifted(qd, &k3.1, h));
        let k4 = (qd4.clone(), self.acceleration(&q4, &qd4, work));
        let (two, sixth) = (Four::splat(2.0), Four::splat(h / 6.0));
        let combine = |x: &[Four], a: &[Four], b: &[Four], c: &[Four], d: &[Four]| -> Vec<Four> {
            (0..x.len())
                .map(|i| x[i] + sixth * (a[i] + two * b[i] + two * c[i] + d[i]))
                .collect()
        };
        (
            combine(q, &k1.0, &k2.0, &k3.0, &k4.0),
            combine(qd, &k1.1, &k2.1, &k3.1, &k4.1),
        )
    }
}
