//! `dynamics identify ROBOT --csv FILE [--floating [--joint-rows]] [--rotors] [--friction KINDS] [--cutoff HZ]
//! [--tolerance X] [--set NAME=VALUE].. [--plot FILE] [--validate FILE [--validate-plot FILE]]
//! [--iterate-weights] [--consistent [--description-out FILE]] [--json]`: the robot's parameters estimated from measured motions and torques.
//!
//! Inverse dynamics is linear in the parameters: `τ = Y(q, q̇, q̈) π`. Each sample k of the file
//! gives one equation per joint, `τ_i(t_k) − τ_spring,i = Y_i(t_k) π` (the description's springs
//! are known, not identified), and the N samples of n joints stack into `τ = Y π + ρ`:
//!
//! * π: the base parameters ([`dynamics_codegen::BaseParameters`]): the combinations of
//!   the links' standard parameters and of the joint terms that τ determines, with `Y` their
//!   reduced regressor of full column rank. The joint terms are those the description gives
//!   (its actuator inertias, its friction) and those asked for on every joint (`--rotors`:
//!   `IA_i`, the coefficient of `q̈_i`; `--friction viscous,coulomb,offset`: `FV_i q̇_i +
//!   FC_i sign(q̇_i) + FO_i`), as `dynamics inspect --base-parameters` takes them.
//! * identifiable parameters: the base parameters are identifiable from some motion, but not
//!   from every one (a joint that never moves, too little excitation). A rank-revealing QR of
//!   the stacked `Y`, columns scaled to unit norm and taken in order, names each column within
//!   `--tolerance` of the span of those before it, with its combination, and leaves it out.
//! * two-step weighted least squares (Gautier and Poignet, 2001): the ordinary fit
//!   `π̂ = argmin ‖Y π − τ‖²`, then per joint `σ_i² = ‖Y_i π̂ − τ_i‖² / (N − c_i)` (c_i the
//!   identified parameters in joint i's equation) and the fit with joint i's rows divided by
//!   σ_i: `π̂_w = argmin Σ_i ‖Y_i π − τ_i‖² / σ_i²`.
//! * standard deviations `σ_π̂k = σ̂ √[(Y_wᵀ Y_w)⁻¹]_kk`, `σ̂² = ‖Y_w π̂_w − τ_w‖² / (nN − b)`,
//!   and `100 σ_π̂k / |π̂_k|` %; the condition number `σ_max / σ_min` of the weighted `Y_w`.
//!
//! With `--cutoff`, q is low-passed before differentiation, and τ and the regressor's columns
//! alike before they are used, one sample in d kept (`dynamics_identification::identify::source`, `::decimate`).
//!
//! `--validate FILE`: the torques of other measurements (read, filtered and with springs
//! subtracted as the fit's) predicted by the estimate, `τ̂ = Y π̂`, and the RMS of
//! `τ − τ̂` per joint reported beside the RMS of τ (`identify::predict`).
//!
//! `--consistent`: beside the plain estimate, standard parameters π with every link's
//! pseudo-inertia `J_i ⪰ 0` minimising `‖R_w (P π) − z_w‖²` (`identify::consistent`), and
//! with `--description-out` the TOML description rewritten with them (`report::description`).
//!
//! `--floating`: the robot on a free-flying base (Pinocchio's free flyer), samples of `q` of
//! `n + 7` values and `v`, `a`, `τ` of `n + 6`; every row of τ fitted, the base's six (the
//! wrench on it) and the joints', or with `--joint-rows` the joints' alone
//! (`Regressor::floating`).
//!
//! `Y` is never held: each joint's rows update a triangular factor as they are read
//! (`identify::measured`), `YᵀY` is never formed, and all of the above comes from the
//! factors. The regressor is evaluated by a tape of only its own nodes of the robot's graph.

use super::values::settings;
use super::{load, load_with_request, robot_failure, usage, write_svg, Failure};
use crate::args::Identify;
use crate::plot::Envelope;
use crate::report::description;
use crate::report::identify::{Report, Row, BASE_ROWS};
use crate::report::identify_figure as figure;
use dynamics_codegen::Parameter;
use dynamics_identification::identify::consistent::Consistent;
use dynamics_identification::identify::predict::Prediction;
use dynamics_identification::sizing::unit;
use dynamics_identification::{identify, predict, Error, Identified, Options, Regressor, Samples};

pub fn run(args: &Identify) -> Result<String, Failure> {
    let (name, regressor, rows, rows_used) = if args.floating {
        floating(args)?
    } else {
        fixed(args)?
    };
    let source = open(&args.csv, &regressor, args.cutoff)?;
    let options = Options {
        tolerance: args.tolerance,
        weight_iterations: args.weight_iterations(),
        consistent: args.consistent,
    };
    let identified = identify(&regressor, &source, &options).map_err(|e| match e {
        Error::Estimate(e) => Failure::File(format!("{}: {e}{}", args.csv, kept(&source))),
        Error::Consistent(e) => Failure::File(format!("{}: {e}", args.csv)),
        e => Failure::File(e.to_string()),
    })?;
    let consistent = consistent(args, &identified)?;
    let figure_of = |path: &str, what: &str, source: &Samples| -> Result<Prediction, Failure> {
        let title = format!("{name}: {what}");
        figure_file(
            &regressor,
            source,
            &identified.estimate,
            path,
            (title, &rows),
        )
    };
    if let Some(path) = &args.plot {
        figure_of(path, "measured and predicted joint torques", &source)?;
    }
    let validation = match &args.validate {
        None => None,
        Some(csv) => {
            let other = open(csv, &regressor, args.cutoff)?;
            let prediction = match &args.validate_plot {
                Some(path) => figure_of(path, &format!("torques of {csv} predicted"), &other)?,
                None => predict(&regressor, &other, &identified.estimate, None)
                    .map_err(|e| Failure::File(e.to_string()))?,
            };
            Some((csv.as_str(), prediction))
        }
    };
    let description = if args.floating {
        "the base parameters of the floating body and the links, the floating body's first \
         (their groupings: the derive's `base_from_standard()` with `base = floating, \
         base_parameters = true`)"
            .to_string()
    } else {
        format!(
            "the base parameters of the links and the joint terms: {} (their groupings: \
             `dynamics inspect --base-parameters` with the same options)",
            regressor.joint_terms()
        )
    };
    let report = Report {
        robot: &name,
        csv: &args.csv,
        method: identified.method,
        filter: source.filter(),
        model: &description,
        springs: regressor.springs().iter().any(Option::is_some),
        tolerance: args.tolerance,
        start: identified.span.0,
        end: identified.span.1,
        rows,
        rows_used,
        linear: regressor.model(),
        estimate: &identified.estimate,
        consistent,
        validation,
    };
    Ok(if args.json {
        report.json()
    } else {
        report.text()
    })
}

/// The robot's name, its regressor, the rows of τ it fits and, where not every joint's, which.
type Fitted = (String, Regressor, Vec<Row>, Option<String>);

/// The robot on its fixed base: a row of τ per coordinate (a mimic joint's torque is carried
/// onto the joint it follows).
fn fixed(args: &Identify) -> Result<Fitted, Failure> {
    let robot = load(&args.robot)?;
    let fields = settings("identify", &robot, &args.set)?;
    let joint_columns = args.joint_terms.columns(&robot);
    let regressor = Regressor::new(&robot, joint_columns, fields)
        .map_err(|e| robot_failure(&args.robot.path, e))?;
    let rows = (robot.coordinates().iter().enumerate())
        .map(|(i, &j)| Row {
            tau: i + 1,
            joint: Some(j + 1),
            base: "",
            unit: unit(robot.joints[j].kind),
        })
        .collect();
    Ok((robot.name, regressor, rows, None))
}

/// `--floating`: the robot on a free-flying base, the base's six rows of τ (the wrench on it,
/// which force plates or the feet's sensors give) and the joints', or with `--joint-rows` the
/// joints' alone (the floating body's parameters, in the base's rows only, then unidentifiable).
fn floating(args: &Identify) -> Result<Fitted, Failure> {
    let not_yet = [
        (
            args.joint_terms.rotors,
            "--rotors: the floating base's regressor has no joint columns yet",
        ),
        (
            !args.joint_terms.friction.is_empty(),
            "--friction: the floating base's regressor has no joint columns yet",
        ),
        (
            args.description_out.is_some(),
            "--description-out: a description's `[floating]` body is not rewritten yet",
        ),
    ];
    if let Some((_, message)) = not_yet.iter().find(|(asked, _)| *asked) {
        return Err(usage("identify", &format!("{message} (with --floating)")));
    }
    let loaded = load_with_request(&args.robot)?;
    let fields = settings("identify", &loaded.robot, &args.set)?;
    let regressor = Regressor::floating(&loaded, fields, args.joint_rows)
        .map_err(|e| robot_failure(&args.robot.path, e))?;
    let robot = &loaded.robot;
    let base = BASE_ROWS.iter().enumerate().map(|(i, &(base, unit))| Row {
        tau: i + 1,
        joint: None,
        base,
        unit,
    });
    let joints = robot.joints.iter().enumerate().map(|(j, joint)| Row {
        tau: 7 + j,
        joint: Some(j + 1),
        base: "",
        unit: unit(joint.kind),
    });
    let n = robot.joints.len();
    let (rows, used) = if args.joint_rows {
        let used = format!(
            "the joints' {n} of τ alone (--joint-rows): the floating body's parameters and the \
             combinations only the base's rows see are not identifiable"
        );
        (joints.collect(), used)
    } else {
        let used = format!(
            "all {} of τ, the base's 6 (the wrench on it in its frame: fx fy fz mx my mz) and \
             the joints' {n}",
            n + 6
        );
        (base.chain(joints).collect(), used)
    };
    Ok((robot.name.clone(), regressor, rows, Some(used)))
}

/// The consistent estimate, if asked for, with its standard parameters' names; the description
/// rewritten with it if asked for.
fn consistent<'i>(
    args: &Identify,
    identified: &'i Identified,
) -> Result<Option<(&'i Consistent, Vec<String>)>, Failure> {
    let Some((standard, found)) = &identified.consistent else {
        return Ok(None);
    };
    if let Some(path) = &args.description_out {
        write_description(
            &args.robot.path,
            path,
            &standard.parameters,
            &found.standard,
        )?;
    }
    let names = standard.parameters.iter().map(|p| p.name()).collect();
    Ok(Some((found, names)))
}

/// The torques the estimate predicts for `source`, drawn against the measured ones into the
/// SVG file `path`, titled `title`, for rows of τ of these joints' numbers and units.
fn figure_file(
    regressor: &Regressor,
    source: &Samples,
    estimate: &dynamics_identification::identify::estimate::Estimate,
    path: &str,
    (title, rows): (String, &[Row]),
) -> Result<Prediction, Failure> {
    let n = regressor.model().joints();
    let mut envelope = Envelope::new(figure::SERIES * n);
    let mut values = vec![0.0; figure::SERIES * n];
    let mut each = |t: f64, measured: &[f64], predicted: &[f64]| {
        figure::values(measured, predicted, &mut values);
        envelope.push(t, &values);
    };
    let prediction = predict(regressor, source, estimate, Some(&mut each))
        .map_err(|e| Failure::File(e.to_string()))?;
    let filtered = source.filter().is_some();
    write_svg(path, &figure::figure(title, rows, filtered, &envelope))?;
    Ok(prediction)
}
/// The description `robot` (TOML) rewritten with the standard parameters `values`, to `path`.
fn write_description(
    robot: &str,
    path: &str,
    parameters: &[Parameter],
    values: &[f64],
) -> Result<(), Failure> {
    if !robot.ends_with(".toml") {
        let message =
            format!("--description-out rewrites a TOML description; `{robot}` is not one");
        return Err(usage("identify", &message));
    }
    let text =
        std::fs::read_to_string(robot).map_err(|e| Failure::File(format!("{robot}: {e}")))?;
    let out = description::rewrite(&text, parameters, values)
        .map_err(|e| Failure::File(format!("{robot}: {e}")))?;
    std::fs::write(path, out).map_err(|e| Failure::File(format!("{path}: {e}")))
}

/// What a filter kept of the samples, for an estimate the samples could not give.
fn kept(source: &Samples) -> String {
    source.filter().map_or(String::new(), |f| {
        format!(
            " (--cutoff {} keeps one sample in {}: {} of the {} samples)",
            f.cutoff,
            f.decimation,
            f.kept(),
            f.read
        )
    })
}

/// The samples of `path` for `regressor`, filtered at `cutoff` if given.
fn open(path: &str, regressor: &Regressor, cutoff: Option<f64>) -> Result<Samples, Failure> {
    Samples::open(path, regressor.columns(), cutoff).map_err(|e| match e {
        Error::Setting(e) => usage("identify", &e),
        e => Failure::File(e.to_string()),
    })
}
