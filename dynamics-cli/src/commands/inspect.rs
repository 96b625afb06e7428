//! `dynamics inspect ROBOT [--latex] [--kinematics | --base-parameters [--rotors]
//! [--friction ..] | --simplified --tolerance .. [--q-min ..] [--q-max ..] [--qd-max ..]
//! [--qdd-max ..]]`: the equations of motion, the hand pose and Jacobians, the base parameters,
//! or τ, M and g pruned within a proven bound, in the book's notation.

use super::eval::usage;
use super::{base_parameters, load, Failure};
use crate::args::{Inspect, Numbers, Simplified};
use dynamics_codegen::derive;
use dynamics_codegen::inspect::{
    inspect, inspect_kinematics, inspect_simplified, render_base_parameters, Envelope, Format,
    JointEnvelope, Limits,
};
use dynamics_codegen::model::{JointKind, Robot};

pub fn run(args: &Inspect) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let mut eq = derive(&robot);
    let format = if args.latex {
        Format::Latex
    } else {
        Format::Text
    };
    if args.base_parameters {
        let columns = args.joint_terms.columns(&robot);
        let base = base_parameters(&mut eq, &robot, &args.robot, &columns)?;
        return Ok(render_base_parameters(&robot.name, &base, format));
    }
    if args.simplified.simplified {
        let (envelope, tolerance) = envelope("inspect", &args.simplified, &robot)?;
        let simplified = inspect_simplified(&eq, &robot, &envelope, &tolerance)
            .map_err(|e| Failure::File(format!("{}: {e}", args.robot.path)))?;
        return Ok(simplified.render(format));
    }
    let inspection = if args.kinematics {
        inspect_kinematics(&eq, &robot, Limits::UNBOUNDED)
    } else {
        inspect(&eq, &robot, Limits::UNBOUNDED)
    };
    Ok(inspection.render(format))
}

/// The envelope and the tolerances asked for: each option one value for every joint or one per
/// joint, else the defaults (±π rad or ±1 m, 2 per s, 5 per s²).
pub(super) fn envelope(
    command: &str,
    args: &Simplified,
    robot: &Robot,
) -> Result<(Envelope, Vec<f64>), Failure> {
    let n = robot.joints.len();
    let per_joint = |option: &str, given: Option<&Numbers>| -> Result<Option<Vec<f64>>, Failure> {
        match given {
            None => Ok(None),
            Some(Numbers(v)) if v.len() == 1 => Ok(Some(vec![v[0]; n])),
            Some(Numbers(v)) if v.len() == n => Ok(Some(v.clone())),
            Some(Numbers(v)) => Err(usage(
                command,
                &format!(
                    "{option}: {} values; give one for every joint or one for each of the {n} joints",
                    v.len()
                ),
            )),
        }
    };
    let tolerance = per_joint("--tolerance", args.tolerance.as_ref())?.unwrap_or_default();
    if let Some(t) = tolerance.iter().find(|t| **t < 0.0) {
        return Err(usage(command, &format!("--tolerance: {t} is negative")));
    }
    let lower = per_joint("--q-min", args.q_min.as_ref())?;
    let upper = per_joint("--q-max", args.q_max.as_ref())?;
    let speed = per_joint("--qd-max", args.qd_max.as_ref())?;
    let acceleration = per_joint("--qdd-max", args.qdd_max.as_ref())?;
    let mut joints = Vec::with_capacity(n);
    for (j, joint) in robot.joints.iter().enumerate() {
        let range = match joint.kind {
            JointKind::Revolute => std::f64::consts::PI,
            JointKind::Prismatic => 1.0,
        };
        let pick = |v: &Option<Vec<f64>>, default: f64| v.as_ref().map_or(default, |v| v[j]);
        let e = JointEnvelope {
            lower: pick(&lower, -range),
            upper: pick(&upper, range),
            speed: pick(&speed, 2.0),
            acceleration: pick(&acceleration, 5.0),
        };
        if e.lower > e.upper {
            let message = format!(
                "joint {}: the range [{}, {}] is empty (--q-min, --q-max)",
                j + 1,
                e.lower,
                e.upper
            );
            return Err(usage(command, &message));
        }
        if e.speed < 0.0 || e.acceleration < 0.0 {
            let message = format!(
                "joint {}: --qd-max and --qdd-max must not be negative",
                j + 1
            );
            return Err(usage(command, &message));
        }
        joints.push(e);
    }
    Ok((Envelope { joints }, tolerance))
}

#[cfg(test)]
mod tests {
    use crate::run;

    const PUMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");

    #[test]
    fn simplified_torques_with_their_bounds() {
        let out = run([
            "inspect",
            PUMA,
            "--simplified",
            "--tolerance",
            "0.5,0.5,0.5,0.01,0.01,0.01",
            "--qd-max",
            "1",
            "--q-min",
            "-1.5",
            "--q-max",
            "1.5",
        ])
        .expect("runs");
        assert!(out.contains("  T1 = "), "{out}");
        // M and g pruned too, each with its report.
        assert!(out.contains("  D11 = ") && out.contains("  D1 = "), "{out}");
        assert!(out.contains("\nD12: ") && out.contains("\nD2: "), "{out}");
        assert!(
            out.contains("θ1 ∈ [-1.5, 1.5], |θ1'| ≤ 1, |θ1''| ≤ 5"),
            "{out}"
        );
        let t2 = out
            .lines()
            .find(|l| l.starts_with("T2: "))
            .expect("T2's report");
        assert!(t2.contains("(tolerance 0.5)"), "{t2}");
        let (kept, total) = t2[4..]
            .split_once(" terms kept")
            .and_then(|(k, _)| k.split_once(" of "))
            .map(|(k, t)| (k.parse::<usize>().unwrap(), t.parse::<usize>().unwrap()))
            .expect("counts");
        assert!(kept < total, "{t2}");
        assert!(out.contains("… and "), "long lists are cut: {out}");
        let latex = run([
            "inspect",
            PUMA,
            "--simplified",
            "--tolerance",
            "1",
            "--latex",
        ])
        .expect("runs");
        assert!(latex.contains("% T1: "), "{latex}");
    }

    #[test]
    fn simplified_usage_errors() {
        let wrong = run(["inspect", PUMA, "--simplified", "--tolerance", "1,2"]).unwrap_err();
        assert!(wrong.contains("--tolerance: 2 values"), "{wrong}");
        let alone = run(["inspect", PUMA, "--simplified"]).unwrap_err();
        assert!(alone.contains("--tolerance"), "{alone}");
        let stray = run(["inspect", PUMA, "--qd-max", "1"]).unwrap_err();
        assert!(stray.contains("--simplified"), "{stray}");
        let empty = run([
            "inspect",
            PUMA,
            "--simplified",
            "--tolerance",
            "1",
            "--q-min",
            "1",
            "--q-max",
            "0",
        ])
        .unwrap_err();
        assert!(empty.contains("is empty"), "{empty}");
        let cart = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robots/niku_example_6_1.toml"
        );
        let param = run(["inspect", cart, "--simplified", "--tolerance", "1"]).unwrap_err();
        assert!(param.contains("T1: the parameter `"), "{param}");
    }
}
