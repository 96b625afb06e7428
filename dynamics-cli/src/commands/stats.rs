//! `dynamics stats ROBOT`: expansion time, operation counts, longest chain of operations and
//! code size per method, and the cost of the readable equations the derive adds.

use super::values::joint_count;
use super::{field_idents, load_with_request, self_fields, type_name, Failure};
use crate::args::Stats;
use dynamics_codegen::model::{Robot, Simplification};
use dynamics_codegen::pipeline::derived_readable;
use dynamics_codegen::{expand_robot, generate, Equations, Generated};
use dynamics_codegen::{Family, Method};
use quote::{quote, ToTokens};
use std::fmt::Write;
use std::time::{Duration, Instant};

/// " in 4 branches" for a tree (one per tip: a joint no other hangs from), nothing for a chain.
fn branches(robot: &Robot) -> String {
    if !robot.is_tree() {
        return String::new();
    }
    let n = robot.dof();
    let tips = (0..n)
        .filter(|&j| (0..n).all(|k| robot.parent(k) != Some(j)))
        .count();
    format!(" in {tips} branches")
}

pub fn run(args: &Stats) -> Result<String, Failure> {
    let file = load_with_request(&args.robot)?;
    if args.floating {
        return floating(args, &file);
    }
    let robot = &file.robot;
    // The file's `[simplify]` as the derive reads it, with the command line's options in
    // place of its keys.
    let request = super::inspect::request("stats", &args.simplified, robot, &file)?;
    let start = Instant::now();
    let eq = file
        .equations(args.families.set(), request.as_ref())
        .map_err(|d| Failure::File(d.to_string()))?;
    let fields = field_idents(&eq, &args.robot.path)?;
    let generated = generate(&eq, self_fields(&fields));
    let elapsed = start.elapsed();
    let mut out = format!(
        "{}: {}{}, graph {} nodes, derived and emitted in {:.1} ms\n",
        robot.name,
        joint_count(robot),
        branches(robot),
        eq.graph.len(),
        elapsed.as_secs_f64() * 1e3
    );
    out += &methods(&generated);
    out += &bounds(&eq);
    // With the signatures, the struct and the forwarding impl around them.
    let krate = quote!(::dynamics_runtime);
    let ty = type_name(&robot.name);
    let items = generated.items(&krate, &ty, &syn::Generics::default(), &|_| None);
    let _ = writeln!(
        out,
        "all items the derive emits: {} bytes",
        items.to_token_stream().to_string().len()
    );
    out += &readable(&eq, robot);
    out += &whole_derive(robot, &ty, &fields, args, request.as_ref());
    Ok(out)
}

/// `--floating`: the robot on a free-flying base, as the derive's `base = floating` traces
/// it, and its methods' table (`FloatingDynamics`: M, h, τ, g, the forward dynamics, M⁻¹).
fn floating(args: &Stats, file: &dynamics_codegen::Loaded) -> Result<String, Failure> {
    let families = args.families.set();
    let supported = [
        Family::Derivatives,
        Family::Regressor,
        Family::BaseParameters,
    ];
    if families.opt_in().any(|f| !supported.contains(&f)) {
        let message = "--floating gives M, h, τ, g, the forward dynamics and M⁻¹, and with \
                       --with the derivatives, the regressor and the base parameters: the other \
                       opt-in families are not supported on a floating base yet";
        return Err(super::usage("stats", message));
    }
    let start = Instant::now();
    let mut eq = file.floating_equations_with(families).map_err(|d| {
        let lines: Vec<String> = d.iter().map(ToString::to_string).collect();
        Failure::File(lines.join("\ndynamics: "))
    })?;
    let fields = field_idents(&eq, &args.robot.path)?;
    let generated = generate(&eq, self_fields(&fields));
    let elapsed = start.elapsed();
    let robot = &file.robot;
    let mut out = format!(
        "{} on a floating base: {} and the base's 6 (NQ {}, NV {}){}, graph {} nodes, derived and emitted in {:.1} ms\n",
        robot.name,
        joint_count(robot),
        eq.dof + 1,
        eq.dof,
        branches(robot),
        eq.graph.len(),
        elapsed.as_secs_f64() * 1e3
    );
    out += &methods(&generated);
    // Every floating derive's too, beside the table (`FloatingContactTerms`), after the frames'
    // kinematics, which it reads.
    if let Some((elapsed, o)) = file.floating_contact_terms(&mut eq) {
        let _ = writeln!(
            out,
            "contact_terms (every frame): {} mul, {} add, {} neg, {} div, {} flops, depth {}; traced and emitted in {:.1} ms",
            o.mul,
            o.add,
            o.neg,
            o.div,
            o.flops(),
            o.depth,
            elapsed.as_secs_f64() * 1e3
        );
    }
    Ok(out)
}

/// The table: per method its operations, depth and bytes; the shared code's bytes; the total.
fn methods(generated: &Generated) -> String {
    let mut out = format!(
        "{:<30} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>6} {:>9}\n",
        "method", "mul", "add", "neg", "div", "trig", "flops", "depth", "bytes"
    );
    let mut total = 0;
    for module in &generated.modules {
        let adjective = module.family.adjective();
        for (function, shared) in [
            ("configuration", &module.configuration),
            ("motion", &module.motion),
        ] {
            if let Some(c) = shared {
                let bytes = c.tokens.to_string().len();
                total += bytes;
                let name = format!("({adjective}{function})");
                let _ = writeln!(
                    out,
                    "{:<30} {:>49} {:>9}",
                    name, "computed once, counted below", bytes
                );
            }
        }
    }
    for m in &generated.methods {
        let bytes = m.body.to_string().len();
        total += bytes;
        let o = m.ops;
        let _ = writeln!(
            out,
            "{:<30} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>6} {:>9}",
            m.name,
            o.mul,
            o.add,
            o.neg,
            o.div,
            o.trig,
            o.flops(),
            o.depth,
            bytes
        );
    }
    for m in generated.methods.iter().filter(|m| m.ops.lanes > 0) {
        let _ = writeln!(
            out,
            "{}: plus {} operations on lanes of tangents (one vector each)",
            m.name, m.ops.lanes
        );
    }
    let _ = writeln!(out, "total generated code: {total} bytes");
    out
}

/// The proven bound of each simplified output over the envelope, with its tolerance and the
/// terms kept of the expanded polynomial; nothing for a robot not simplified.
fn bounds(eq: &Equations) -> String {
    let Some(s) = &eq.simplified else {
        return String::new();
    };
    let mut out = String::from(
        "proven bounds of |exact - simplified| over the envelope (tolerance; terms kept of the expanded polynomial):\n",
    );
    // The vectors first (T, C, D), then M's upper triangle.
    let order = [
        Method::InverseDynamicsSimplified,
        Method::CoriolisTorquesSimplified,
        Method::GravityTorquesSimplified,
        Method::MassMatrixSimplified,
    ];
    for output in order.into_iter().filter_map(|m| s.output(m)) {
        if let Some(f) = output.fallback {
            let name = if output.method == Method::MassMatrixSimplified {
                "Dij"
            } else {
                output.letter
            };
            let _ = writeln!(out, "  {name:<5} exact (bound 0): {f}");
            continue;
        }
        for (name, _, b) in output.named_bounds() {
            let _ = writeln!(
                out,
                "  {name:<5} {:>10.3e} ({:.3e}; {} of {})",
                b.bound, b.tolerance, b.kept, b.terms
            );
        }
    }
    out
}

/// What the derive adds for `EQUATIONS` and `EQUATIONS_LATEX`, and for the rustdoc of the
/// kinematic methods, within its limits.
fn readable(eq: &Equations, robot: &Robot) -> String {
    let start = Instant::now();
    let added = derived_readable(eq, robot);
    let elapsed = start.elapsed();
    let state = |complete: bool| {
        if complete {
            "complete"
        } else {
            "capped: some sections point to `dynamics inspect`"
        }
    };
    format!(
        "readable equations in the derive: {:.1} ms, {} + {} bytes (text + LaTeX), {}; \
         kinematics in the methods' rustdoc: {} bytes, {}\n",
        elapsed.as_secs_f64() * 1e3,
        added.text,
        added.latex,
        state(added.complete),
        added.docs,
        state(added.docs_complete),
    )
}

/// The time of the whole expansion as `#[derive(Dynamics)]` runs it on the parsed robot (trace,
/// emission, readable equations and docs), the fastest of `runs`, in wall-clock time and in the
/// thread's CPU time: the others' work on a shared machine only ever adds to the first, and
/// leaves out of the second the time the thread waits for a core.
fn whole_derive(
    robot: &Robot,
    ty: &syn::Ident,
    fields: &[syn::Ident],
    args: &Stats,
    simplify: Option<&Simplification>,
) -> String {
    let runs = args.runs;
    let input: syn::DeriveInput = syn::parse_quote!(struct #ty { #(#fields: f64,)* });
    let mut wall = Duration::MAX;
    let mut cpu: Option<Duration> = None;
    let mut progress = crate::budget::Progress::new("dynamics stats", "runs", runs as f64);
    for run in 0..runs {
        progress.update(run as f64);
        let (start, start_cpu) = (Instant::now(), thread_cpu_time());
        let tokens = expand_robot(&input, robot, args.families.set(), simplify);
        let (elapsed, end_cpu) = (start.elapsed(), thread_cpu_time());
        drop(tokens);
        wall = wall.min(elapsed);
        if let (Some(a), Some(b)) = (start_cpu, end_cpu) {
            let used = b.saturating_sub(a);
            cpu = Some(cpu.map_or(used, |c| c.min(used)));
        }
    }
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let cpu = cpu.map_or(String::new(), |c| {
        format!(" ({:.1} ms of the thread's CPU time)", ms(c))
    });
    format!(
        "the derive's whole expansion: {:.1} ms{cpu}, the fastest of {runs} runs\n",
        ms(wall)
    )
}

/// The CPU time this thread has used, where the system tells it.
#[cfg(unix)]
fn thread_cpu_time() -> Option<Duration> {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `clock_gettime` writes one `timespec` through the pointer, which points to one.
    #[allow(unsafe_code)]
    let status = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    let secs = u64::try_from(t.tv_sec).ok()?;
    let nanos = u32::try_from(t.tv_nsec).ok()?;
    (status == 0).then(|| Duration::new(secs, nanos))
}

#[cfg(not(unix))]
fn thread_cpu_time() -> Option<Duration> {
    None
}

#[cfg(test)]
mod tests {
    use crate::run;

    const PUMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");

    /// The simplified methods' rows beside the exact ones, and each output's bound within its
    /// tolerance; with a zero tolerance nothing is dropped.
    #[test]
    fn simplified_methods_and_their_bounds() {
        let args = ["stats", PUMA, "--runs", "1", "--simplified", "--tolerance"];
        let out = run(args.iter().copied().chain(["0.5,0.5,0.5,0.01,0.01,0.01"])).expect("runs");
        let methods = [
            "inverse_dynamics",
            "mass_matrix",
            "coriolis_torques",
            "gravity_torques",
        ];
        for method in methods {
            assert!(out.contains(&format!("\n{method} ")), "{out}");
            assert!(out.contains(&format!("\n{method}_simplified ")), "{out}");
        }
        let t1 = out
            .lines()
            .find(|l| l.trim_start().starts_with("T1 "))
            .expect("T1");
        let numbers: Vec<f64> = t1
            .split(|c: char| c.is_whitespace() || "();".contains(c))
            .filter_map(|w| w.parse().ok())
            .collect();
        assert!(numbers[0] > 0.0 && numbers[0] <= 0.5, "{t1}");
        assert!(numbers[2] < numbers[3], "terms dropped: {t1}");
        let exact = run(args.iter().copied().chain(["0"])).expect("runs");
        assert!(
            exact.contains("  T1       0.000e0 (0.000e0; 275 of 275)"),
            "{exact}"
        );
        let plain = run(["stats", PUMA, "--runs", "1"]).expect("runs");
        assert!(
            !plain.contains("_simplified") && !plain.contains("proven"),
            "{plain}"
        );
        let wrong = run(args.iter().copied().chain(["1,2"])).unwrap_err();
        assert!(
            format!("{wrong:?}").contains("--tolerance: 2 values"),
            "{wrong:?}"
        );
    }

    /// An output too large to prune is printed as exact, with why, beside the pruned ones.
    #[test]
    fn an_output_left_exact_says_why() {
        let random5 = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../tests/data/reference/robots/random5.json"
        );
        let args = [
            "stats",
            random5,
            "--runs",
            "1",
            "--simplified",
            "--tolerance",
        ];
        let out = run(args.iter().copied().chain(["0.4,0.3,0.2,0.1,0.05,0.02"])).expect("runs");
        assert!(
            out.contains("\n  T     exact (bound 0): its pruned expansion keeps "),
            "{out}"
        );
        assert!(!out.contains("\n  T1 "), "{out}");
        assert!(out.contains("\n  D12 "), "{out}");
    }

    /// `--floating`: Solo 12 from its URDF and from its description file (`[floating]`), the
    /// floating base's methods, the same operations from both; a file without `[floating]`
    /// says so.
    #[test]
    fn a_robot_on_a_floating_base() {
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/");
        let urdf = format!("{root}urdf/floating/solo12.urdf");
        let file = format!("{root}floating/solo12.toml");
        let row = |out: &str, method: &str| {
            let line = out.lines().find(|l| l.starts_with(&format!("{method} ")));
            line.expect(method)
                .split_whitespace()
                .skip(1)
                .take(5)
                .collect::<Vec<_>>()
                .join(" ")
        };
        let from_urdf = run(["stats", urdf.as_str(), "--floating", "--runs", "1"]).expect("runs");
        assert!(
            from_urdf.contains("on a floating base: 12 joints and the base's 6 (NQ 19, NV 18)"),
            "{from_urdf}"
        );
        let from_file = run(["stats", file.as_str(), "--floating", "--runs", "1"]).expect("runs");
        for method in [
            "mass_matrix",
            "bias_forces",
            "inverse_dynamics",
            "generalized_gravity",
            "forward_dynamics",
            "mass_matrix_inverse",
        ] {
            assert_eq!(row(&from_urdf, method), row(&from_file, method), "{method}");
        }
        // The opt-in families a floating base has, and one it has not.
        let with = [
            "stats",
            urdf.as_str(),
            "--floating",
            "--runs",
            "1",
            "--with",
        ];
        let identification = run(with.into_iter().chain(["regressor,base_parameters"]));
        let identification = identification.expect("runs");
        for method in [
            "regressor",
            "standard_parameters",
            "base_regressor",
            "base_parameters",
        ] {
            assert!(!row(&identification, method).is_empty(), "{method}");
        }
        let refused = run(with.into_iter().chain(["tip_kinematics"])).unwrap_err();
        assert!(
            format!("{refused:?}").contains("not supported"),
            "{refused:?}"
        );
        // Beside joint friction and actuator inertia the derivatives are traced; the regressor
        // has no columns for them, refused as the derive refuses it.
        let terms = format!("{root}../tests/data/floating/solo12_joint_terms.toml");
        let with = with.map(|w| {
            if w == urdf.as_str() {
                terms.as_str()
            } else {
                w
            }
        });
        let derivatives = run(with.into_iter().chain(["derivatives"])).expect("runs");
        assert!(!row(&derivatives, "inverse_dynamics_derivatives").is_empty());
        let refused = run(with.into_iter().chain(["regressor"])).unwrap_err();
        assert!(
            format!("{refused:?}").contains("joint friction or actuator inertia"),
            "{refused:?}"
        );
        let fixed = format!("{root}puma560.toml");
        let wrong = run(["stats", fixed.as_str(), "--floating", "--runs", "1"]).unwrap_err();
        assert!(
            format!("{wrong:?}").contains("no `[floating]` table"),
            "{wrong:?}"
        );
    }
}
