//! Wall-clock time per call of the generated dynamics of the four 6-joint reference robots and
//! the 7-joint Panda, in Rust alone, with the protocol of the C++ program of `bench/pinocchio/`.
//! The comparison with Pinocchio is that program's (`bench/run`), which calls the generated code
//! through `bench/ffi` and times both sides in turn; this binary is for comparing builds of the
//! generated code, the other implementations (`--all`) and instruction counts.
//!
//! ```text
//! cargo run --release -p dynamics-bench --bin timings [-- [--all] [--robot R] [--function F]]
//! ```
//!
//! # What is measured
//!
//! For each robot (`puma560`, `stanford`, `ur5`, `random5`, each derived with
//! `#[derive(Dynamics)]` from `tests/data/reference/robots/<robot>.json`, `panda`, from
//! `tests/data/panda/robot.json`, and `ur5_dh`, the D-H twin of `robots/urdf/ur5.urdf`, from
//! `robots/ur5_urdf_dh.toml`, and `ur5_urdf`, from the URDF itself), the generated `f64`
//! methods:
//!
//! | function | method |
//! |---|---|
//! | `tau` | `inverse_dynamics(&q, &qd, &qdd)` |
//! | `M` | `mass_matrix(&q)` |
//! | `g` | `gravity_torques(&q)` |
//! | `C` | `coriolis_matrix(&q, &qd)` |
//! | `h` | `bias_torques(&q, &qd)` (`C qd + g`, Pinocchio's non-linear effects) |
//! | `fk` | `hand_pose(&q)` |
//! | `J` | `hand_jacobian_in_base(&q)` |
//! | `JtF` | `joint_torques_for_base_wrench(&q, &wrench)`, a wrench fixed per sample |
//! | `fd` | `forward_dynamics(&q, &qd, &qdd)` (the sample's q̈ as torques) |
//! | `Minv` | `mass_matrix_inverse(&q)` |
//! | `dtau` | `inverse_dynamics_derivatives(&q, &qd, &qdd)` |
//! | `dqdd` | `forward_dynamics_derivatives(&q, &qd, &qdd)` (the sample's q̈ as torques) |
//! | `Y` | `regressor_into(&q, &qd, &qdd, &mut y)` (the joint torque regressor, into one buffer) |
//! | `YB` | `base_regressor_into(&q, &qd, &qdd, &mut y)` (the base regressor, into one buffer) |
//!
//! With `--all`, three more for context, computed from the same description:
//!
//! | function | implementation |
//! |---|---|
//! | `tau_reference` | the book's O(n⁴) Lagrangian method, `dynamics_reference::Robot::inverse_dynamics` |
//! | `tau_rnea` | a plain numeric recursive Newton-Euler, `dynamics_codegen::Numeric::inverse_dynamics` |
//! | `M_crba` | a plain numeric composite rigid body algorithm, `Numeric::mass_matrix` |
//!
//! `tau_rnea` and `M_crba` loop over the joints at run time and return `Vec`s, so their time
//! includes heap allocation; they are a baseline, not a tuned implementation.
//!
//! # Protocol
//!
//! The inputs are the 20 samples `(q, qd, qdd)` of the robot's data file,
//! used cyclically. After 10,000 warm-up calls, 31 batches of 20,000 calls are timed with
//! `std::time::Instant`; a batch's time per call is its elapsed time divided by its number of
//! calls, and the median over the batches is printed. (`tau_reference`, thousands of times
//! slower, gets 10 warm-up calls and 31 batches of 20.) Inputs and outputs go through
//! `std::hint::black_box`, so no call is hoisted out of the loop or optimized away.
//!
//! Output, on stdout, one line per (robot, function): robot, function and median ns per call,
//! separated by single tabs, e.g. `puma560\ttau\t41.3`.
//!
//! `--fastest` prints instead the fastest of 300 batches of 2,000 calls: on a machine shared
//! with noisy neighbours, the figure least disturbed by them, for comparing two builds of the
//! generated code run alternately (a median moves with the neighbours' spells). It is not the
//! protocol of the Pinocchio side.
//!
//! On stderr, one sanity line per robot: the generated `tau` must equal the data's `tau`
//! (Pinocchio 4.1.0) within 1e-9 (scaled as `max|a − b| / max(1, max|b|)`), else the program
//! exits with status 1 before timing that robot. `--robot` and `--function` restrict the run
//! to one robot or one function.
//!
//! # Instruction counts (callgrind)
//!
//! `--calls N --robot R --function F` makes exactly `N` calls of one function (any of the names
//! above), cycling over the samples as in the timed loop, and prints nothing: no timing, no
//! sanity check. Under callgrind this gives a deterministic instruction count; subtracting a
//! `--calls 0` run removes the start-up cost (reading the JSON files, building the numeric
//! models):
//!
//! ```text
//! cargo build --release -p dynamics-bench --bin timings
//! valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.out \
//!     target/release/timings --calls 10000 --robot puma560 --function tau
//! valgrind --tool=callgrind --callgrind-out-file=/tmp/cg0.out \
//!     target/release/timings --calls 0 --robot puma560 --function tau
//! callgrind_annotate /tmp/cg.out | head    # "PROGRAM TOTALS", minus that of /tmp/cg0.out,
//!                                          # divided by 10000 = instructions per call
//! ```

use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

use dynamics_bench::{Panda, Puma560, Random5, Sample, Stanford, Ur5, Ur5Dh, Ur5Urdf, ROBOTS};
use dynamics_codegen::Numeric;
use dynamics_runtime::{Dynamics, DynamicsBaseParameters, DynamicsDerivatives, DynamicsRegressor};

/// The generated methods, timed by default.
const GENERATED: [&str; 14] = [
    "tau", "M", "g", "C", "h", "fk", "J", "JtF", "fd", "Minv", "dtau", "dqdd", "Y", "YB",
];
/// The other implementations, timed with `--all`.
const EXTRA: [&str; 3] = ["tau_reference", "tau_rnea", "M_crba"];

/// Largest accepted scaled error of the generated `tau` against the reference data.
const TOLERANCE: f64 = 1e-9;

/// Number of calls of each phase of a timing.
#[derive(Clone, Copy, Debug)]
struct Protocol {
    warm_up: usize,
    batches: usize,
    calls_per_batch: usize,
}

/// The protocol shared with the Pinocchio benchmark.
const PROTOCOL: Protocol = Protocol {
    warm_up: 10_000,
    batches: 31,
    calls_per_batch: 20_000,
};

/// The same with fewer calls, for the book's method.
const SLOW_PROTOCOL: Protocol = Protocol {
    warm_up: 10,
    batches: 31,
    calls_per_batch: 20,
};

/// The protocol of `--fastest`: many short batches, of which the fastest is kept.
const FASTEST_PROTOCOL: Protocol = Protocol {
    warm_up: 10_000,
    batches: 300,
    calls_per_batch: 2_000,
};

/// Time per call or exact number of calls.
#[derive(Clone, Copy, Debug)]
enum Mode {
    /// Time with the protocol; return the median ns per call.
    Time,
    /// Time with [`FASTEST_PROTOCOL`]; return the fastest batch's ns per call.
    Fastest,
    /// Make exactly this many calls, untimed (for callgrind).
    Calls(usize),
}

/// The implementations other than the generated code, for `--all` and the sanity line.
struct Others {
    /// Numeric RNEA / CRBA. Allocates `Vec`s on every call; that is part of what it costs.
    numeric: Numeric,
    /// The book's method.
    book: dynamics_reference::Robot,
}

/// Calls `f` on the samples cyclically: the warm-up and the timed batches of `protocol`,
/// returning the median ns per call (in [`Mode::Fastest`], the fastest batch's, over many shorter
/// batches), or, in [`Mode::Calls`], exactly that many calls.
fn drive<O, const N: usize>(
    samples: &[Sample<N>],
    protocol: Protocol,
    mode: Mode,
    mut f: impl FnMut(&Sample<N>) -> O,
) -> Option<f64> {
    assert!(!samples.is_empty(), "no samples");
    let mut k = 0;
    let mut call = || {
        black_box(f(black_box(&samples[k])));
        k += 1;
        if k == samples.len() {
            k = 0;
        }
    };
    if let Mode::Calls(n) = mode {
        for _ in 0..n {
            call();
        }
        return None;
    }
    // The book's method keeps its own short protocol.
    let protocol = match mode {
        Mode::Fastest if protocol.calls_per_batch > SLOW_PROTOCOL.calls_per_batch => {
            FASTEST_PROTOCOL
        }
        _ => protocol,
    };
    for _ in 0..protocol.warm_up {
        call();
    }
    let mut per_call: Vec<f64> = (0..protocol.batches)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..protocol.calls_per_batch {
                call();
            }
            start.elapsed().as_nanos() as f64 / protocol.calls_per_batch as f64
        })
        .collect();
    if let Mode::Fastest = mode {
        return per_call.iter().copied().reduce(f64::min);
    }
    Some(median(&mut per_call))
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    }
}

/// Times (or calls, in [`Mode::Calls`]) `function` of `robot`.
fn measure<
    R: DynamicsDerivatives<N> + DynamicsRegressor<N> + DynamicsBaseParameters<N, B>,
    const N: usize,
    const B: usize,
>(
    robot: &R,
    others: &Others,
    samples: &[Sample<N>],
    function: &str,
    mode: Mode,
) -> Option<f64> {
    let robot = black_box(robot);
    let (p, s) = (PROTOCOL, samples);
    match function {
        "tau" => drive(s, p, mode, |x| robot.inverse_dynamics(&x.q, &x.qd, &x.qdd)),
        "M" => drive(s, p, mode, |x| robot.mass_matrix(&x.q)),
        "g" => drive(s, p, mode, |x| robot.gravity_torques(&x.q)),
        "C" => drive(s, p, mode, |x| robot.coriolis_matrix(&x.q, &x.qd)),
        "h" => drive(s, p, mode, |x| robot.bias_torques(&x.q, &x.qd)),
        "fk" => drive(s, p, mode, |x| robot.hand_pose(&x.q)),
        "J" => drive(s, p, mode, |x| robot.hand_jacobian_in_base(&x.q)),
        "JtF" => drive(s, p, mode, |x| {
            // a wrench from the sample, so that it is not a constant of the loop
            let wrench = [x.qd[0], x.qd[1], x.qd[2], x.qdd[0], x.qdd[1], x.qdd[2]];
            robot.joint_torques_for_base_wrench(&x.q, &wrench)
        }),
        // the samples' qdd as torques: the robots' M is not positive definite everywhere (the
        // reference UR5), where the result is then an error, as cheap to make
        "fd" => drive(s, p, mode, |x| robot.forward_dynamics(&x.q, &x.qd, &x.qdd)),
        "Minv" => drive(s, p, mode, |x| robot.mass_matrix_inverse(&x.q)),
        "dtau" => drive(s, p, mode, |x| {
            robot.inverse_dynamics_derivatives(&x.q, &x.qd, &x.qdd)
        }),
        "dqdd" => drive(s, p, mode, |x| {
            robot.forward_dynamics_derivatives(&x.q, &x.qd, &x.qdd)
        }),
        "Y" => {
            // Into one buffer, as bench/ffi writes the caller's.
            let mut y = [[[0.0; 10]; N]; N];
            drive(s, p, mode, |x| {
                robot.regressor_into(&x.q, &x.qd, &x.qdd, black_box(&mut y));
            })
        }
        "YB" => {
            let mut y = [[0.0; B]; N];
            drive(s, p, mode, |x| {
                robot.base_regressor_into(&x.q, &x.qd, &x.qdd, black_box(&mut y));
            })
        }
        "tau_reference" => drive(s, SLOW_PROTOCOL, mode, |x| {
            others.book.inverse_dynamics(&x.q, &x.qd, &x.qdd)
        }),
        "tau_rnea" => drive(s, p, mode, |x| {
            others.numeric.inverse_dynamics(&x.q, &x.qd, &x.qdd)
        }),
        "M_crba" => drive(s, p, mode, |x| others.numeric.mass_matrix(&x.q)),
        _ => unreachable!("function names are checked when parsing the arguments"),
    }
}

/// Worst scaled error of `tau` over the samples.
fn worst_error<const N: usize>(samples: &[Sample<N>], tau: impl Fn(&Sample<N>) -> Vec<f64>) -> f64 {
    samples
        .iter()
        .map(|s| dynamics_bench::scaled_error(&tau(s), &s.tau))
        .fold(0.0, f64::max)
}

/// The sanity line of `name` on stderr; `false` if the generated `tau` is off.
fn sanity<R: Dynamics<N>, const N: usize>(
    robot: &R,
    name: &str,
    others: &Others,
    samples: &[Sample<N>],
    all: bool,
) -> bool {
    let generated = worst_error(samples, |s| {
        robot.inverse_dynamics(&s.q, &s.qd, &s.qdd).to_vec()
    });
    let ok = generated <= TOLERANCE;
    let mut line = format!(
        "{name}: generated tau vs reference data over {} samples: max scaled error {generated:.1e} ({})",
        samples.len(),
        if ok { "ok, <= 1e-9" } else { "FAILED, > 1e-9" },
    );
    if all {
        let rnea = worst_error(samples, |s| {
            others.numeric.inverse_dynamics(&s.q, &s.qd, &s.qdd)
        });
        let book = worst_error(samples, |s| {
            others
                .book
                .inverse_dynamics(&s.q, &s.qd, &s.qdd)
                .as_slice()
                .to_vec()
        });
        line += &format!("; tau_rnea {rnea:.1e}, tau_reference {book:.1e}");
    }
    eprintln!("{line}");
    ok
}

/// Runs the selected functions of one robot; `false` if its sanity check failed.
fn run<
    R: DynamicsDerivatives<N> + DynamicsRegressor<N> + DynamicsBaseParameters<N, B>,
    const N: usize,
    const B: usize,
>(
    robot: &R,
    name: &str,
    functions: &[&str],
    args: &Args,
) -> bool {
    let samples = dynamics_bench::samples::<N>(name);
    let others = Others {
        numeric: dynamics_bench::numeric(name),
        book: dynamics_bench::book(name),
    };
    if let Some(n) = args.calls {
        for function in functions {
            measure(robot, &others, &samples, function, Mode::Calls(n));
        }
        return true;
    }
    if !sanity(robot, name, &others, &samples, args.all) {
        return false;
    }
    for function in functions {
        let mode = if args.fastest {
            Mode::Fastest
        } else {
            Mode::Time
        };
        let ns =
            measure(robot, &others, &samples, function, mode).expect("a timed run returns a time");
        println!("{name}\t{function}\t{ns:.1}");
    }
    true
}

#[derive(Debug, Default)]
struct Args {
    all: bool,
    robot: Option<String>,
    function: Option<String>,
    calls: Option<usize>,
    fastest: bool,
}

const USAGE: &str = "\
usage: timings [--all] [--fastest] [--robot ROBOT] [--function FUNCTION]
       timings --calls N --robot ROBOT --function FUNCTION

  --all          also time tau_reference, tau_rnea and M_crba
  --fastest      the fastest of 300 batches of 2,000 calls, not the median of 31 of 20,000
  --robot R      only robot R: puma560, stanford, ur5, random5, panda, ur5_dh, ur5_urdf
  --function F   only function F: tau, M, g, C, h, fk, J, JtF, fd, Minv, dtau, dqdd, Y, tau_reference, tau_rnea, M_crba
  --calls N      make exactly N calls of one function, print nothing (for callgrind)";

fn parse_args() -> Result<Args, String> {
    let mut args = Args::default();
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--all" => args.all = true,
            "--fastest" => args.fastest = true,
            "--robot" => args.robot = Some(value()?),
            "--function" => args.function = Some(value()?),
            "--calls" => {
                let v = value()?;
                args.calls = Some(v.parse().map_err(|_| format!("--calls {v}: not a count"))?);
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(format!("unknown argument {arg}")),
        }
    }
    if let Some(r) = &args.robot {
        if !ROBOTS.contains(&r.as_str()) {
            return Err(format!("unknown robot {r}"));
        }
    }
    if let Some(f) = &args.function {
        if !GENERATED.contains(&f.as_str()) && !EXTRA.contains(&f.as_str()) {
            return Err(format!("unknown function {f}"));
        }
    }
    if args.calls.is_some() && (args.robot.is_none() || args.function.is_none()) {
        return Err("--calls needs --robot and --function".into());
    }
    Ok(args)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("timings: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let functions: Vec<&str> = match &args.function {
        Some(f) => vec![f.as_str()],
        None if args.all => GENERATED.iter().chain(&EXTRA).copied().collect(),
        None => GENERATED.to_vec(),
    };
    for name in ROBOTS {
        if args.robot.as_deref().is_some_and(|r| r != name) {
            continue;
        }
        let ok = match name {
            "puma560" => run(&Puma560, name, &functions, &args),
            "stanford" => run(&Stanford, name, &functions, &args),
            "ur5" => run(&Ur5, name, &functions, &args),
            "random5" => run(&Random5, name, &functions, &args),
            "panda" => run(&Panda, name, &functions, &args),
            "ur5_dh" => run(&Ur5Dh, name, &functions, &args),
            "ur5_urdf" => run(&Ur5Urdf, name, &functions, &args),
            _ => unreachable!("every robot of ROBOTS has a struct"),
        };
        if !ok {
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}
