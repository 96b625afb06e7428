//! `dynamics identify ROBOT --csv FILE [--rotors] [--friction KINDS] [--cutoff HZ]
//! [--tolerance X] [--set NAME=VALUE].. [--plot FILE] [--validate FILE [--validate-plot FILE]]
//! [--iterate-weights] [--consistent [--description-out FILE]] [--json]`: the robot's parameters estimated from measured motions and torques.
//!
//! Inverse dynamics is linear in the parameters: `τ = Y(q, q̇, q̈) π`. Each sample k of the file
//! gives one equation per joint, `τ_i(t_k) − τ_spring,i = Y_i(t_k) π` (the description's springs
//! are known, not identified), and the N samples of n joints stack into `τ = Y π + ρ`:
//!
//! * π: the base parameters (`dynamics_codegen::trace::base_parameters`): the combinations of
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
//! alike before they are used, one sample in d kept (`identify::source`, `identify::decimate`).
//!
//! `--validate FILE`: the torques of other measurements (read, filtered and with springs
//! subtracted as the fit's) predicted by the estimate, `τ̂ = Y π̂`, and the RMS of
//! `τ − τ̂` per joint reported beside the RMS of τ (`identify::predict`).
//!
//! `--consistent`: beside the plain estimate, standard parameters π with every link's
//! pseudo-inertia `J_i ⪰ 0` minimising `‖R_w (P π) − z_w‖²` (`identify::consistent`), and
//! with `--description-out` the TOML description rewritten with them (`identify::description`).
//!
//! `Y` is never held: each joint's rows update a triangular factor as they are read
//! (`identify::measured`), `YᵀY` is never formed, and all of the above comes from the
//! factors. The regressor is evaluated by a tape of only its own nodes of the robot's graph.

use super::eval::{settings, usage};
use super::size::write_svg;
use super::{base_parameters, load, Failure};
use crate::args::Identify;
use crate::identify::base;
use crate::identify::consistent::{consistent, Consistent, Problem};
use crate::identify::description;
use crate::identify::estimate::estimate;
use crate::identify::figure;
use crate::identify::measured::Measured;
use crate::identify::model::LinearModel;
use crate::identify::predict::{predict, Prediction};
use crate::identify::report::Report;
use crate::identify::rows::{each_row, Springs};
use crate::identify::source::Source;
use crate::plot::Envelope;
use crate::sizing::unit;
use crate::trajectory::Columns;
use dynamics_codegen::derive;
use dynamics_codegen::model::Robot;
use dynamics_codegen::trace::base_parameters::Parameter;

pub fn run(args: &Identify) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let fields = settings("identify", &robot, &args.set)?;
    let mut eq = derive(&robot);
    let joint_columns = args.joint_terms.columns(&robot);
    let base = base_parameters(&mut eq, &robot, &args.robot, &joint_columns)?;
    let model = LinearModel::new(&base::entries(&eq, &base, &fields)).map_err(Failure::File)?;
    let springs = springs(&robot, &robot.fields(), &fields);
    let columns = Columns {
        joints: model.joints(),
        torques: true,
    };
    let source = open(&args.csv, columns, args.cutoff)?;
    let (mut measured, method, span) = measure(&model, &source, &springs)?;
    let estimate = estimate(&mut measured, args.tolerance, args.weight_iterations())
        .map_err(|e| Failure::File(format!("{}: {e}{}", args.csv, kept(&source))))?;
    let consistent = args
        .consistent
        .then(|| {
            let standard = base::standard(&eq, &base, &joint_columns, &fields);
            consistent_estimate(args, &mut measured, &estimate, &standard)
        })
        .transpose()?;
    let units: Vec<&str> = robot.joints.iter().map(|j| unit(j.kind)).collect();
    let figure_of = |path: &str, what: &str, source: &Source| -> Result<Prediction, Failure> {
        let mut envelope = Envelope::new(figure::SERIES * model.joints());
        let prediction = predict(&model, source, &springs, &estimate, Some(&mut envelope))
            .map_err(Failure::File)?;
        let title = format!("{}: {what}", robot.name);
        let filtered = source.filter().is_some();
        write_svg(path, &figure::figure(title, &units, filtered, &envelope))?;
        Ok(prediction)
    };
    if let Some(path) = &args.plot {
        figure_of(path, "measured and predicted joint torques", &source)?;
    }
    let validation = match &args.validate {
        None => None,
        Some(csv) => {
            let other = open(csv, columns, args.cutoff)?;
            let prediction = match &args.validate_plot {
                Some(path) => figure_of(path, &format!("torques of {csv} predicted"), &other)?,
                None => {
                    predict(&model, &other, &springs, &estimate, None).map_err(Failure::File)?
                }
            };
            Some((csv.as_str(), prediction))
        }
    };
    let description = format!(
        "the base parameters of the links and the joint terms: {} (their groupings: \
         `dynamics inspect --base-parameters` with the same options)",
        base::describe(&joint_columns)
    );
    let report = Report {
        robot: &robot.name,
        csv: &args.csv,
        method,
        filter: source.filter(),
        model: &description,
        springs: springs.iter().any(Option::is_some),
        tolerance: args.tolerance,
        start: span.0,
        end: span.1,
        units,
        linear: &model,
        estimate: &estimate,
        consistent: consistent.as_ref(),
        validation,
    };
    Ok(if args.json {
        report.json()
    } else {
        report.text()
    })
}

/// The consistent estimate, with the standard parameters' names; the description rewritten
/// with it if asked for.
fn consistent_estimate(
    args: &Identify,
    measured: &mut Measured,
    estimate: &crate::identify::estimate::Estimate,
    standard: &base::Standard,
) -> Result<(Consistent, Vec<String>), Failure> {
    let links = measured.joints.len();
    // Offset friction may have either sign; the other joint terms dissipate or add inertia.
    let joint_terms: Vec<bool> = standard.parameters[10 * links..]
        .iter()
        .map(|p| !matches!(p, Parameter::Joint { index: 3, .. }))
        .collect();
    let problem = Problem {
        links,
        joint_terms: &joint_terms,
        map: &standard.map,
        described: &standard.described,
    };
    let names = standard.parameters.iter().map(|p| p.name()).collect();
    let found = consistent(measured, estimate, &problem)
        .map_err(|e| Failure::File(format!("{}: {e}", args.csv)))?;
    if let Some(path) = &args.description_out {
        write_description(
            &args.robot.path,
            path,
            &standard.parameters,
            &found.standard,
        )?;
    }
    Ok((found, names))
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

/// Per joint, the description's spring `(k, rest)`, if any, at these fields' values.
fn springs(robot: &Robot, names: &[String], values: &[f64]) -> Vec<Option<(f64, f64)>> {
    let field = |f: &str| names.iter().position(|n| n == f).map(|k| values[k]);
    robot
        .joints
        .iter()
        .map(|j| {
            let spring = j.link.spring.as_ref()?;
            // Every field has a value (`parameters` checked), and a spring has no joint variable.
            let value = |v: &dynamics_codegen::model::Value| v.eval(&field).unwrap_or(f64::NAN);
            Some((value(&spring.stiffness), value(&spring.rest)))
        })
        .collect()
}

/// One pass over the samples into the joints' factors; how q̇ and q̈ were had, and the time
/// span.
fn measure(
    model: &LinearModel,
    source: &Source,
    springs: &Springs,
) -> Result<(Measured, &'static str, (f64, f64)), Failure> {
    let mut measured = Measured::new(model.columns.clone(), model.names.len());
    let mut span = (f64::NAN, f64::NAN);
    let method = each_row(model, source, springs, |t, entries, torques| {
        if span.0.is_nan() {
            span.0 = t;
        }
        span.1 = t;
        let mut start = 0;
        for (i, columns) in model.columns.iter().enumerate() {
            measured.push(i, &entries[start..start + columns.len()], torques[i]);
            start += columns.len();
        }
    })
    .map_err(Failure::File)?;
    Ok((measured, method, span))
}

/// What a filter kept of the samples, for an estimate the samples could not give.
fn kept(source: &Source) -> String {
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

/// The samples of `path`, filtered at `cutoff` if given.
fn open(path: &str, columns: Columns, cutoff: Option<f64>) -> Result<Source, Failure> {
    Source::open(path, columns, cutoff).map_err(|e| {
        if e.starts_with("--cutoff") {
            usage("identify", &e)
        } else {
            Failure::File(e)
        }
    })
}
