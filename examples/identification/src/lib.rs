//! What the identification examples share: excitation, measurement, identification and
//! validation, end to end, for any robot the derive knows.
//!
//! 1. **Excite** ([`dynamics_identification::excite`](fn@dynamics_identification::excite)): a
//!    periodic motion within the joints' limits whose base
//!    regressor is well conditioned.
//! 2. **Measure**: here simulated. A controller tracking the motion applies, up to its
//!    tracking error, the inverse dynamics along it, `τ = M(q) q̈ + C(q, q̇) q̇ + g(q) + f(q̇)`,
//!    evaluated by the derive's generated code; each joint's torque gets Gaussian noise of
//!    standard deviation [`NOISE`] times that joint's RMS torque over the motion.
//! 3. **Identify** ([`dynamics_identification::identify`](fn@dynamics_identification::identify)):
//!    the base parameters by weighted least squares, with
//!    standard deviations, beside the description's (the truth here, which the simulation used).
//! 4. **Validate** ([`dynamics_identification::predict`]): the torques of another motion
//!    (another seed's, not optimised), measured likewise, predicted by the estimates; the RMS of
//!    the prediction error is printed per joint (`dynamics identify --validate-plot` draws it).
//! 5. **Use**: the estimates loaded into the generated code (`base_parameters = true`): the
//!    other motion's torques predicted again, `τ̂ = Y_B(q, q̇, q̈) π̂_B` by `base_regressor`,
//!    as a controller would compute them; their errors are the validation's, to rounding (two
//!    implementations of `Y_B`: the generated code and the library's tape).
//!
//! The library under `dynamics excite` and `dynamics identify`, `dynamics_identification`, is
//! called directly. Files go to a directory of the system's temporary directory.

use dynamics_codegen::front;
use dynamics_codegen::trace::base_parameters::JointColumns;
use dynamics_codegen::Source;
use dynamics_identification::excite::limits::joint_limits;
use dynamics_identification::identify::estimate::Estimate;
use dynamics_identification::identify::predict::Prediction;
use dynamics_identification::{excite, identify, predict, Excited, Motion, Options};
use dynamics_identification::{Regressor, Samples};
use dynamics_runtime::DynamicsBaseParameters;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The torque noise, as a fraction of each joint's RMS torque.
pub const NOISE: f64 = 0.01;

/// The largest prediction error the example accepts, as a fraction of a joint's RMS torque. The
/// noise is 1 %, and so is the error on the joints whose torque is large; on a joint with
/// little torque (the PUMA 560's last: 5·10⁻⁵ N m RMS) `identify`'s two-step weights leave a
/// few % more: σ_i comes from the ordinary fit, whose residual there is the other joints'
/// noise seen through the shared parameters, not the joint's own noise, so its rows are
/// weighted thousands of times too little (`docs/excitation.md`).
pub const PREDICTION: f64 = 0.05;

/// Normal deviates from a seed (xorshift64, Box-Muller).
pub struct Normal(u64);

impl Normal {
    #[must_use]
    pub fn new(seed: u64) -> Normal {
        // SplitMix64 of the seed: a small seed as xorshift's state would give small states,
        // hence uniform deviates near 0 and Box-Muller outliers, for its first draws.
        let mut z = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        Normal((z ^ (z >> 31)).max(1))
    }

    pub fn sample(&mut self) -> f64 {
        let mut uniform = || {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let (u, v) = (uniform(), uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// Reads the trajectory `t,q..,qd..,qdd..` at `path` and writes to `out` the same with the
/// torques of `robot` along it and noise of [`NOISE`] times each joint's RMS torque appended
/// (`t,q..,qd..,qdd..,tau..`), the file `identify` reads. The noise's standard deviations.
///
/// # Panics
/// A trajectory that is not `excite`'s, or a file that cannot be written.
pub fn measure<const N: usize>(
    robot: &impl dynamics_runtime::Dynamics<N>,
    path: &Path,
    out: &Path,
    seed: u64,
) -> [f64; N] {
    let text = std::fs::read_to_string(path).expect("the trajectory");
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect())
        .collect();
    let joint = |row: &[f64], group: usize| -> [f64; N] {
        core::array::from_fn(|j| row[1 + group * N + j])
    };
    let torques: Vec<[f64; N]> = rows
        .iter()
        .map(|r| robot.inverse_dynamics(&joint(r, 0), &joint(r, 1), &joint(r, 2)))
        .collect();
    let sigma: [f64; N] = core::array::from_fn(|j| {
        let squares: f64 = torques.iter().map(|t| t[j] * t[j]).sum();
        NOISE * (squares / torques.len() as f64).sqrt()
    });
    let mut noise = Normal::new(seed);
    let names: Vec<String> = (1..=N).map(|i| format!("tau{i}")).collect();
    let mut file = format!("{header},{}\n", names.join(","));
    for (line, tau) in text.lines().skip(1).zip(&torques) {
        let measured: Vec<String> = (0..N)
            .map(|j| (tau[j] + sigma[j] * noise.sample()).to_string())
            .collect();
        let _ = writeln!(file, "{line},{}", measured.join(","));
    }
    std::fs::write(out, file).expect("write the measurements");
    sigma
}

/// A scratch directory for the example `name`.
fn directory(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("dynamics-identify-{name}"));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir
}

/// The search's evaluations for the motion to identify from, as `dynamics excite`'s default.
const EVALUATIONS: usize = 3000;

/// The periods of that motion written and measured.
const PERIODS: usize = 3;

/// The example end to end on `robot`, read from `source` by the library (its joint terms those
/// its description gives); `name` names its files. Panics if an estimate is more than five
/// standard deviations from the truth, a joint's prediction error on the other motion more than
/// [`PREDICTION`] of its RMS torque, or the generated code's predictions are not the library's.
pub fn example<R, const N: usize, const B: usize>(robot: &R, source: Source<'_>, name: &str)
where
    R: DynamicsBaseParameters<N, B>,
{
    let dir = directory(name);
    let described = dynamics_codegen::load(&source)
        .unwrap_or_else(|e| panic!("{}: {e:?}", source.path))
        .robot;
    let columns = described
        .joints
        .iter()
        .map(JointColumns::described)
        .collect();
    let regressor = Regressor::new(&described, columns, Vec::new()).expect("the base regressor");
    let urdf = source.is_urdf().then(|| {
        let text = std::fs::read_to_string(source.path).expect("the URDF");
        front::joint_limits(&text, source.chain).expect("the URDF's limits")
    });
    let limits: Vec<_> = joint_limits(&described, urdf.as_deref(), [None; 4])
        .expect("the joints' limits")
        .iter()
        .map(|l| l.limits)
        .collect();
    let (motion, other) = (dir.join("excite.csv"), dir.join("other.csv"));
    let started = Instant::now();
    let form = Motion::default();
    let excited = excite(&regressor, limits.clone(), &form, 1, EVALUATIONS, |_| {})
        .expect("an exciting motion");
    excite_step(&regressor, &excited, started.elapsed().as_secs_f64());
    write_motion(&excited, PERIODS, &motion);
    // Another motion for the validation: another seed's first random guess.
    let guess = excite(&regressor, limits, &form, 2, 1, |_| {}).expect("another motion");
    write_motion(&guess, 1, &other);
    let (measured, measured_other) = (dir.join("measured.csv"), dir.join("measured_other.csv"));
    let sigma = measure(robot, &motion, &measured, 11);
    measure(robot, &other, &measured_other, 12);
    println!(
        "2. measure: the generated inverse dynamics along both motions, with noise of {} % of \
         each joint's RMS torque (σ = {})",
        100.0 * NOISE,
        list(&sigma)
    );
    let open = |path: &Path| {
        Samples::open(&path.to_string_lossy(), regressor.columns(), None).expect("the samples")
    };
    let identified =
        identify(&regressor, &open(&measured), &Options::default()).expect("an estimate");
    let worst = estimates(&regressor, &identified.estimate);
    let prediction = predict(
        &regressor,
        &open(&measured_other),
        &identified.estimate,
        None,
    )
    .expect("the predictions");
    let relative = validation(&prediction);
    use_step(
        robot,
        &regressor,
        &identified.estimate,
        &prediction,
        &measured_other,
    );
    assert!(
        worst < 5.0,
        "an estimate {worst:.1} standard deviations off"
    );
    assert!(
        relative < 100.0 * PREDICTION,
        "a prediction error of {relative:.2} %"
    );
}

/// Writes `periods` periods of the motion, and the first sample of the next (at rest, where the
/// motion started), as `t,q..,qd..,qdd..` to `path`, as `dynamics excite --csv` does.
fn write_motion(excited: &Excited, periods: usize, path: &Path) {
    let n = excited.design.series.len();
    let header: Vec<String> = ["q", "qd", "qdd"]
        .iter()
        .flat_map(|g| (1..=n).map(move |i| format!("{g}{i}")))
        .collect();
    let mut file = format!("t,{}\n", header.join(","));
    for k in 0..=periods * excited.grid.samples() {
        let states = excited.states(k);
        let groups = [
            states.iter().map(|s| s.q).collect::<Vec<_>>(),
            states.iter().map(|s| s.qd).collect(),
            states.iter().map(|s| s.qdd).collect(),
        ];
        let values: Vec<String> = groups.iter().flatten().map(f64::to_string).collect();
        let _ = writeln!(file, "{},{}", excited.time(k), values.join(","));
    }
    std::fs::write(path, file).expect("write the motion");
}

/// Step 1: prints what the search found, in `seconds`.
fn excite_step(regressor: &Regressor, excited: &Excited, seconds: f64) {
    println!(
        "1. excite: {} base parameters; a motion of {PERIODS} periods of {} s within the joints' \
         limits; condition number {:.1} (the first guess's {:.1}), in {seconds:.1} s",
        regressor.names().len(),
        excited.grid.period,
        excited.design.condition,
        excited.design.initial_condition,
    );
}

/// Step 5: prints the generated code's prediction errors with `estimate` on the file at `path`;
/// panics where they are not the library's `prediction`'s.
fn use_step<R, const N: usize, const B: usize>(
    robot: &R,
    regressor: &Regressor,
    estimate: &Estimate,
    prediction: &Prediction,
    path: &Path,
) where
    R: DynamicsBaseParameters<N, B>,
{
    let generated = use_estimates(robot, regressor, estimate, path);
    println!(
        "5. use: the estimates in the generated base_regressor, on the other motion: RMS error \
         per joint {}",
        list(&generated)
    );
    for (j, (error, validated)) in generated.iter().zip(&prediction.error_rms).enumerate() {
        assert!(
            (error - validated).abs() <= 1e-9 * validated,
            "joint {}: {error} from the generated code, {validated} from the library",
            j + 1
        );
    }
}

/// `estimate` as the generated code's `π̂_B`, and per joint the RMS error of `Y_B π̂_B` against
/// the torques measured in the file at `path` (`t,q..,qd..,qdd..,tau..`).
fn use_estimates<R, const N: usize, const B: usize>(
    robot: &R,
    regressor: &Regressor,
    estimate: &Estimate,
    path: &Path,
) -> [f64; N]
where
    R: DynamicsBaseParameters<N, B>,
{
    assert_eq!(estimate.values.len(), B, "every base parameter estimated");
    assert!(
        estimate.unidentified.is_empty(),
        "every base parameter identified"
    );
    // The library's order is the generated code's: the description's values agree.
    let described = robot.base_parameters::<f64>();
    let largest = described.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, (ours, theirs)) in regressor
        .model()
        .described
        .iter()
        .zip(described)
        .enumerate()
    {
        let name = &regressor.names()[k];
        assert!(
            (ours - theirs).abs() <= 1e-12 * largest,
            "{name}: {ours}, {theirs}"
        );
    }
    let estimates: [f64; B] = core::array::from_fn(|b| estimate.values[b]);
    let text = std::fs::read_to_string(path).expect("the measurements");
    let (mut squares, mut samples) = ([0.0; N], 0.0);
    for line in text.lines().skip(1) {
        let row: Vec<f64> = line
            .split(',')
            .map(|x| x.parse().expect("a number"))
            .collect();
        let joint = |group: usize| -> [f64; N] { core::array::from_fn(|j| row[1 + group * N + j]) };
        let y = robot.base_regressor(&joint(0), &joint(1), &joint(2));
        for (j, (y_j, tau)) in y.iter().zip(joint(3)).enumerate() {
            let predicted: f64 = y_j.iter().zip(&estimates).map(|(a, b)| a * b).sum();
            squares[j] += (tau - predicted).powi(2);
        }
        samples += 1.0;
    }
    squares.map(|s| (s / samples).sqrt())
}

/// Prints the estimates beside the truth; the largest error in standard deviations.
fn estimates(regressor: &Regressor, e: &Estimate) -> f64 {
    println!(
        "3. identify: {} samples, condition number {:.1}; the {} base parameters:\n   {:<8} \
         {:>13} {:>13} {:>11} {:>8}",
        e.samples,
        e.condition,
        e.values.len(),
        "name",
        "true",
        "estimate",
        "std dev",
        "error/σ"
    );
    let mut worst = 0.0f64;
    let described = &regressor.model().described;
    for (k, name) in regressor.names().iter().enumerate() {
        let (truth, estimate, deviation) = (described[k], e.values[k], e.deviations[k]);
        let error = (estimate - truth) / deviation;
        worst = worst.max(error.abs());
        println!("   {name:<8} {truth:>13.6} {estimate:>13.6} {deviation:>11.2e} {error:>8.2}");
    }
    let unidentified = e.unidentified.len();
    println!("   not identifiable from these data: {unidentified}; the worst error {worst:.2} σ");
    worst
}

/// Prints the validation's errors per joint; the largest relative to the joint's RMS torque, %.
fn validation(p: &Prediction) -> f64 {
    println!(
        "4. validate: the other motion's {} samples, predicted by the estimates:\n   {:>5} \
         {:>12} {:>12} {:>9}",
        p.samples, "joint", "RMS τ", "RMS error", "relative"
    );
    let mut worst = 0.0f64;
    for (j, (rms, error)) in p.measured_rms.iter().zip(&p.error_rms).enumerate() {
        let relative = 100.0 * error / rms;
        worst = worst.max(relative);
        println!(
            "   {:>5} {rms:>12.4} {error:>12.4} {relative:>8.2} %",
            j + 1
        );
    }
    worst
}

fn list(values: &[f64]) -> String {
    let parts: Vec<String> = values.iter().map(|v| format!("{v:.3e}")).collect();
    format!("[{}]", parts.join(", "))
}
