//! `dynamics inspect ROBOT [--latex] [--kinematics | --base-parameters [--rotors]
//! [--friction ..] | --simplified --tolerance .. [--q-min ..] [--q-max ..] [--qd-max ..]
//! [--qdd-max ..] | --floating]`: the equations of motion, the hand pose and Jacobians, the base
//! parameters, τ, M and g pruned within a proven bound, in the book's notation, or a floating
//! base's M, h, g and τ in Pinocchio's coordinates.

use super::eval::usage;
use super::{load_with_request, simplification, Failure};
use crate::args::{Inspect, Numbers, Simplified};
use dynamics_codegen::model::{Robot, Simplification};
use dynamics_codegen::pipeline::Format;
use dynamics_codegen::{Loaded, Readable};

pub fn run(args: &Inspect) -> Result<String, Failure> {
    let file = load_with_request(&args.robot)?;
    let format = if args.latex {
        Format::Latex
    } else {
        Format::Text
    };
    if args.floating {
        return file.floating_readable(format).map_err(|d| {
            let lines: Vec<String> = d.iter().map(ToString::to_string).collect();
            Failure::File(lines.join("\ndynamics: "))
        });
    }
    let columns;
    let simplified;
    let what = if args.base_parameters {
        columns = args.joint_terms.columns(&file.robot);
        Readable::BaseParameters(&columns)
    } else if args.simplified.simplified {
        let Some(s) = request("inspect", &args.simplified, &file.robot, &file)? else {
            return Err(usage("inspect", "--simplified needs --tolerance T"));
        };
        simplified = s;
        Readable::Simplified(&simplified)
    } else if args.kinematics {
        Readable::Kinematics
    } else {
        Readable::Motion
    };
    file.readable(what, format)
        .map_err(|d| Failure::File(d.to_string()))
}

/// The simplified models asked for: the description file's `[simplify]` (a URDF's `<limit>`s
/// the defaults), each option of the command line in place of the table's key; `None` where
/// neither asks. Each option is one value for every joint or one per joint (per coordinate on
/// a robot with mimic joints, which follow theirs).
pub(super) fn request(
    command: &str,
    args: &Simplified,
    robot: &Robot,
    file: &Loaded,
) -> Result<Option<Simplification>, Failure> {
    let n = robot.coordinates().len();
    let each = if robot.has_mimics() {
        "coordinate"
    } else {
        "joint"
    };
    let options = [
        ("tolerance", args.tolerance.as_ref()),
        ("rated", args.rated.as_ref()),
        ("tolerance_percent", args.tolerance_percent.as_ref()),
        ("q_min", args.q_min.as_ref()),
        ("q_max", args.q_max.as_ref()),
        ("qd_max", args.qd_max.as_ref()),
        ("qdd_max", args.qdd_max.as_ref()),
    ];
    let mut overrides = Vec::new();
    for (key, given) in options {
        let Some(Numbers(v)) = given else { continue };
        if v.len() != 1 && v.len() != n {
            let message = format!(
                "--{}: {} values; give one for every {each} or one for each of the {n} {each}s",
                key.replace('_', "-"),
                v.len()
            );
            return Err(usage(command, &message));
        }
        overrides.push((key, v.clone()));
    }
    let tolerance = args.tolerance.is_some() || args.tolerance_percent.is_some();
    if args.simplified && !tolerance && !file.asks_simplified() {
        let message = format!(
            "--simplified needs --tolerance T (or --tolerance-percent P): `{}` has no \
             `[simplify]` table to take it from",
            file.path
        );
        return Err(usage(command, &message));
    }
    simplification(file, &overrides, command)
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
        // M, C q̇ and g pruned too, each with its report.
        assert!(out.contains("  D11 = ") && out.contains("  D1 = "), "{out}");
        assert!(out.contains("\nD12: ") && out.contains("\nD2: "), "{out}");
        assert!(out.contains("  C1 = ") && out.contains("\nC1: "), "{out}");
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
        assert!(
            empty.contains("--q-min (1) is above --q-max (0)"),
            "{empty}"
        );
        let cart = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robots/niku_example_6_1.toml"
        );
        let param = run(["inspect", cart, "--simplified", "--tolerance", "1"]).unwrap_err();
        assert!(param.contains("T1: the parameter `"), "{param}");
    }
}
