//! The harness of the C header tests: a robot's header and traced equations, a C driver that
//! calls every function of the header at given states and prints the results, every C
//! compiler found, and the check of every function against the graph evaluated in `f64`.

#![allow(dead_code)] // each test file uses its part

mod batch;
mod builds;
mod simplified;

pub use builds::{compile_and_run, compile_and_run_builds, compilers, Reach};

use dynamics_codegen::emit_c::{functions, header, prefix, Function, Precision, Returns};
use dynamics_codegen::method::{Argument, Method};
use dynamics_codegen::symbolic::{NodeId, Var};
use dynamics_codegen::trace::Shape;
use dynamics_codegen::{derive, front, Equations, Family, FamilySet};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace root, where `dynamics` runs so that the header's first line names
/// `robots/...`.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// One state at which the driver calls every function.
pub struct State {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    pub tau: Vec<f64>,
}

/// Component `k` of the tips' wrenches the tips' statics are called with: tip t's is
/// [`WRENCH`] times t + 1.
pub fn tip_wrench(k: usize) -> f64 {
    WRENCH[k % 6] * (k / 6 + 1) as f64
}

/// The length of the driver's `wrenches` array, 6 per tip, where the robot has tips (a
/// variable the driver sets but no function reads would be an error under `-Werror`).
pub fn tip_wrenches_length(robot: &Robot) -> Option<usize> {
    let tips = robot.eq.tips.as_ref()?.names.len();
    (tips > 0).then_some(6 * tips)
}

/// The wrench every statics function is called with.
pub const WRENCH: [f64; 6] = [3.0, -2.0, 5.0, 0.5, -0.25, 1.5];

/// A robot's header, its equations traced in process, and its functions.
pub struct Robot {
    pub name: String,
    pub header: String,
    pub eq: Equations,
    pub functions: Vec<Function>,
    /// The values of the robot's parameters (struct fields) the driver passes.
    pub params: Vec<f64>,
    /// More of the driver's statements, at each state `s` after the functions' calls: those
    /// of functions beyond the method table's (a floating base's kinematics, contacts).
    pub calls: String,
    /// How far a solve's `double` result (M⁻¹, the forward dynamics) may be from the graph's
    /// evaluation, scaled: 1e-12, more where M's condition number amplifies the rounding of
    /// sums written in another order (the G1's).
    pub solve_tolerance: f64,
}

impl Robot {
    /// The robot of equations `eq` named `name`, its header written in process, called with
    /// these parameter values.
    pub fn new(name: &str, eq: Equations, params: Vec<f64>) -> Robot {
        assert_eq!(params.len(), eq.fields.len(), "a value per parameter");
        let name_prefix = prefix(name);
        let header = header(&eq, name, &name_prefix, "the test");
        let name = name_prefix;
        let functions = functions(&eq, &name);
        Robot {
            name,
            header,
            eq,
            functions,
            params,
            calls: String::new(),
            solve_tolerance: 1e-12,
        }
    }

    /// The robot of equations `eq` named `name`, its header the command line's, without
    /// parameters.
    pub fn emitted(name: &str, eq: Equations, header: String) -> Robot {
        let name = prefix(name);
        let functions = functions(&eq, &name);
        Robot {
            name,
            header,
            eq,
            functions,
            params: vec![],
            calls: String::new(),
            solve_tolerance: 1e-12,
        }
    }
}

/// The robot of a description file, its header written by `dynamics emit --lang c`.
pub fn robot(file: &str) -> Robot {
    robot_with(file, &[])
}

/// [`robot`] with the opt-in families `with` (`--with derivatives,regressor`).
pub fn robot_with(file: &str, with: &[&str]) -> Robot {
    robot_from(file, None, with)
}

/// The robot of a URDF file, the chain from `base` to `tip`.
pub fn urdf_robot(file: &str, base: &str, tip: &str) -> Robot {
    robot_from(file, Some((base, Some(tip))), &[])
}

/// The robot of a URDF file, every branch below `base`, with the families `with`.
pub fn urdf_tree_robot_with(file: &str, base: &str, with: &[&str]) -> Robot {
    robot_from(file, Some((base, None)), with)
}

/// The header `dynamics emit --lang c FILE EXTRA.. [--with WITH]` writes; it must be ASCII.
pub fn emitted_header(file: &str, extra: &[&str], with: &[&str]) -> String {
    let list = with.join(",");
    let mut args = vec!["emit", "--lang", "c", file];
    args.extend(extra);
    if !with.is_empty() {
        args.extend(["--with", &list]);
    }
    let out = Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(&args)
        .current_dir(root())
        .output()
        .expect("run dynamics");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let header = String::from_utf8(out.stdout).expect("UTF-8");
    // Every C toolchain reads ASCII; not all read UTF-8 in comments.
    assert!(header.is_ascii(), "the header of {file} is not ASCII");
    header
}

/// The opt-in families named in `with`.
pub fn families(with: &[&str]) -> FamilySet {
    with.iter()
        .map(|name| Family::from_name(name).expect("a family"))
        .fold(FamilySet::default(), FamilySet::with)
}

/// The robot of a description file or (with a base and a tip, or every branch) a URDF file,
/// with the families `with`.
fn robot_from(file: &str, chain: Option<(&str, Option<&str>)>, with: &[&str]) -> Robot {
    let mut extra = vec![];
    if let Some((base, tip)) = chain {
        extra.extend(["--base", base]);
        extra.extend(tip.iter().flat_map(|tip| ["--tip", tip]));
    }
    let header = emitted_header(file, &extra, with);
    let text = std::fs::read_to_string(root().join(file)).expect("description file");
    let loaded = match chain {
        Some((base, tip)) => {
            let chain = front::Chain {
                base: Some(base),
                tip,
                tips: &[],
            };
            front::load_urdf(file, &text, chain, true).unwrap_or_else(|_| panic!("{file}"))
        }
        None => front::load(file, &text).expect("a valid description"),
    };
    let mut eq = derive(&loaded.robot);
    eq.add_families(&loaded.robot, families(with));
    simplified::add(&mut eq, &loaded.robot, loaded.simplify, file);
    Robot::emitted(&loaded.robot.name, eq, header)
}

/// 1 on a floating base, whose `q` has the base's x before the graph's coordinates, else 0.
pub fn q_shift(eq: &Equations) -> usize {
    usize::from(eq.families.contains(Family::Floating))
}

/// `{a, b, c}`, each number exactly (Rust's shortest round trip, which C reads back).
pub fn c_array(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|x| format!("{x:?}")).collect();
    format!("{{{}}}", items.join(", "))
}

/// The driver: every function at every state, one line per result array, `name:part sample
/// status values...`.
pub fn driver(robot: &Robot, states: &[State]) -> String {
    let n = robot.eq.dof;
    let nq = n + q_shift(&robot.eq);
    let mut c = format!(
        "#include <stdio.h>\n#define DYNAMICS_BATCH\n#include \"{}.h\"\n\n\
         static void show(const char *f, int s, int r, const double *x, int n) {{\n    \
         int i;\n    printf(\"%s %d %d\", f, s, r);\n    \
         for (i = 0; i < n; ++i) printf(\" %.17g\", x[i]);\n    printf(\"\\n\");\n}}\n\n\
         static void show_f32(const char *f, int s, int r, const float *x, int n) {{\n    \
         int i;\n    printf(\"%s %d %d\", f, s, r);\n    \
         for (i = 0; i < n; ++i) printf(\" %.9g\", (double)x[i]);\n    printf(\"\\n\");\n}}\n\n\
         int main(void) {{\n    int s, i;\n    static const double wrench[6] = {};\n",
        robot.name,
        c_array(&WRENCH)
    );
    for (name, pick, len) in [
        ("q", (|s: &State| &s.q) as fn(&State) -> &Vec<f64>, nq),
        ("qd", |s| &s.qd, n),
        ("qdd", |s| &s.qdd, n),
        ("tau", |s| &s.tau, n),
    ] {
        let rows: Vec<String> = states.iter().map(|s| c_array(pick(s))).collect();
        c.push_str(&format!(
            "    static const double {name}[{}][{len}] = {{{}}};\n",
            states.len(),
            rows.join(", ")
        ));
    }
    if let Some(w) = tip_wrenches_length(robot) {
        let tips: Vec<f64> = (0..w).map(tip_wrench).collect();
        c.push_str(&format!(
            "    static const double wrenches[{w}] = {};\n    float wrenches_f[{w}];\n    \
             for (i = 0; i < {w}; ++i) wrenches_f[i] = (float)wrenches[i];\n",
            c_array(&tips)
        ));
    }
    let k = robot.params.len();
    if k > 0 {
        c.push_str(&format!(
            "    static const double params[{k}] = {};\n    float params_f[{k}];\n    \
             for (i = 0; i < {k}; ++i) params_f[i] = (float)params[i];\n",
            c_array(&robot.params)
        ));
    }
    c.push_str(&format!(
        "    float wrench_f[6], q_f[{nq}], qd_f[{n}], qdd_f[{n}], tau_f[{n}];\n    \
         for (i = 0; i < 6; ++i) wrench_f[i] = (float)wrench[i];\n    \
         (void)wrench_f; /* a robot without statics (a floating base's) reads none */\n    \
         for (s = 0; s < {}; ++s) {{\n        for (i = 0; i < {n}; ++i) {{\n            \
         q_f[i] = (float)q[s][i];\n            qd_f[i] = (float)qd[s][i];\n            \
         qdd_f[i] = (float)qdd[s][i];\n            tau_f[i] = (float)tau[s][i];\n        }}\n{}",
        states.len(),
        // A floating base's q is one longer (the base's x first).
        if nq > n {
            format!("        for (i = {n}; i < {nq}; ++i) q_f[i] = (float)q[s][i];\n")
        } else {
            String::new()
        }
    ));
    for f in &robot.functions {
        c.push_str(&call(f));
    }
    c.push_str(&robot.calls);
    c.push_str("    }\n");
    c.push_str(&batch::calls(robot, states.len()));
    c.push_str("    return 0;\n}\n");
    c
}

/// The block calling `f` at state `s` and printing its result.
pub fn call(f: &Function) -> String {
    let (ty, show, at) = match f.precision {
        Precision::Double => ("double", "show", "[s]"),
        Precision::Single => ("float", "show_f32", "_f"),
    };
    let params = match f.precision {
        Precision::Double => "params",
        Precision::Single => "params_f",
    };
    let inputs = f.arguments.iter().map(|&(a, _)| match (a, f.precision) {
        (Argument::Wrench, Precision::Double) => "wrench".to_owned(),
        (Argument::Wrenches, Precision::Double) => "wrenches".to_owned(),
        (Argument::Wrenches, Precision::Single) => "wrenches_f".to_owned(),
        (a, _) => format!("{}{at}", a.name()),
    });
    let mut args: Vec<String> = (f.parameters > 0)
        .then(|| params.to_owned())
        .into_iter()
        .chain(inputs)
        .collect();
    let mut block = "        {\n            int r = 0;\n".to_owned();
    for (k, array) in f.outputs.iter().enumerate() {
        let dims: String = array.dims.iter().map(|d| format!("[{d}]")).collect();
        block.push_str(&format!("            {ty} out{k}{dims};\n"));
        args.push(format!("out{k}"));
    }
    let call = format!("{}({})", f.name, args.join(", "));
    match f.returns {
        Returns::Nothing => block.push_str(&format!("            {call};\n")),
        Returns::Status => block.push_str(&format!("            r = {call};\n")),
        Returns::Value => {
            block.push_str(&format!(
                "            const {ty} v = {call};\n            {show}(\"{}:0\", s, r, &v, 1);\n",
                f.name
            ));
        }
    }
    for (k, array) in f.outputs.iter().enumerate() {
        let len: usize = array.dims.iter().product();
        block.push_str(&format!(
            "            {show}(\"{}:{k}\", s, r, (const {ty} *)out{k}, {len});\n",
            f.name
        ));
    }
    block.push_str("        }\n");
    block
}

/// What the driver printed: by `(name:part, sample)`, the status and the values.
pub type Printed = BTreeMap<(String, usize), (i32, Vec<f64>)>;

pub fn parse(output: &str) -> Printed {
    output
        .lines()
        .map(|line| {
            let mut words = line.split_whitespace();
            let key = words.next().expect("a name").to_owned();
            let sample = words.next().and_then(|w| w.parse().ok()).expect("a sample");
            let status = words.next().and_then(|w| w.parse().ok()).expect("a status");
            let values = words.map(|w| w.parse().expect("a number")).collect();
            ((key, sample), (status, values))
        })
        .collect()
}

/// One build of a driver, run: by which compiler, with which sines and cosines, and what it
/// printed.
pub struct Run {
    /// The compiler, and `-DDYNAMICS_OWN_SINCOS` where it has that.
    pub label: String,
    pub printed: Printed,
}

/// Every node of the graph at `state`, as `dynamics eval` evaluates it.
pub fn evaluate(eq: &Equations, params: &[f64], state: &State) -> Vec<f64> {
    // A floating base's coordinate k is entry k + 1 of its q.
    let q = &state.q[q_shift(eq)..];
    let base = |v: Var, offsets: &[f64]| -> f64 {
        let i = |k: u16| usize::from(k);
        // A robot with mimic joints keeps its joints' leaves past its coordinates in the graph,
        // read by no output: zero (as `Equations::evaluate` has them).
        let at = |x: &[f64], k: u16| x.get(i(k)).copied().unwrap_or(0.0);
        match v {
            Var::Q(k) => at(q, k),
            Var::SinQ(k) => (at(q, k) + at(offsets, k)).sin(),
            Var::CosQ(k) => (at(q, k) + at(offsets, k)).cos(),
            Var::Qd(k) => at(&state.qd, k),
            Var::Qdd(k) => at(&state.qdd, k),
            Var::Tau(k) => at(&state.tau, k),
            Var::Wrench(k) => WRENCH[i(k)],
            Var::TipWrench(k) => tip_wrench(i(k)),
            Var::Param(k) => params[i(k)],
            Var::Inertial(_) | Var::Exact(_) => f64::NAN,
        }
    };
    let zeros = vec![0.0; eq.dof];
    let first = eq.graph.eval(|v| base(v, &zeros));
    let offsets: Vec<f64> = eq
        .angle_offsets
        .iter()
        .map(|o| o.map_or(0.0, |id| first[id.index()]))
        .collect();
    eq.graph.eval(|v| base(v, &offsets))
}

/// The nodes of each array a function prints, in its order.
pub fn parts(shape: &Shape) -> Vec<Vec<NodeId>> {
    let flat = |m: &[Vec<NodeId>]| m.iter().flatten().copied().collect::<Vec<_>>();
    let stack = |s: &[Vec<Vec<NodeId>>]| s.iter().flat_map(|m| flat(m)).collect::<Vec<_>>();
    match *shape {
        Shape::Scalar(id) => vec![vec![id]],
        Shape::Vector(v) | Shape::SolvedVector { vector: v, .. } => vec![v.to_vec()],
        Shape::Matrix(m) | Shape::SolvedMatrix { matrix: m, .. } => vec![flat(m)],
        Shape::Stack(s)
        | Shape::Lanes {
            stack: s,
            solved: None,
            ..
        } => vec![stack(s)],
        Shape::SolvedStack {
            vector, stack: s, ..
        } => vec![vector.to_vec(), stack(s)],
        // `∂q̈` in lanes: `q̈` beside the matrices, as a solved stack.
        Shape::Lanes {
            stack: s,
            solved: Some(solved),
            ..
        } => vec![solved.vector.to_vec(), stack(s)],
    }
}

/// `want`'s largest magnitude, 1 for an array of zeros (`scaled_error`'s scale).
pub fn want_scale(want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if scale == 0.0 {
        1.0
    } else {
        scale
    }
}

/// The largest difference between `got` and `want`, over `want`'s largest magnitude (1 for
/// an array of zeros, whose differences are then absolute).
pub fn scaled_error(got: &[f64], want: &[f64]) -> f64 {
    assert_eq!(got.len(), want.len());
    let scale = want_scale(want);
    got.iter()
        .zip(want)
        .map(|(g, w)| (g - w).abs() / scale)
        .fold(0.0, f64::max)
}

/// What a C function printed at sample `s`, part `k`.
pub fn printed<'p>(printed: &'p Printed, name: &str, k: usize, s: usize) -> &'p (i32, Vec<f64>) {
    printed
        .get(&(format!("{name}:{k}"), s))
        .unwrap_or_else(|| panic!("{name} printed nothing at sample {s}"))
}

/// Every function against the graph: `double` to 1e-12 (the header adds each sum's terms in
/// the emission's order, `Sums::plan`, not the graph's, and its sines and cosines are within
/// an ulp of the libm's), `float` to `f32_tolerance`; and its batch over every state, state by
/// state, bit for bit the single-state call.
pub fn check_against_graph(robot: &Robot, states: &[State], run: &Run) {
    let (out, cc) = (&run.printed, &run.label);
    for (s, state) in states.iter().enumerate() {
        let values = evaluate(&robot.eq, &robot.params, state);
        for f in &robot.functions {
            let tolerance = match f.precision {
                Precision::Double if solves(f.method) => robot.solve_tolerance,
                Precision::Double => 1e-12,
                Precision::Single => f32_tolerance(f.method),
            };
            let shape = f.method.shape(&robot.eq);
            for (k, part) in parts(&shape).iter().enumerate() {
                let want: Vec<f64> = part.iter().map(|id| values[id.index()]).collect();
                let (status, got) = printed(out, &f.name, k, s);
                // A result near zero (q̈ where τ balances gravity) is the rounding of the
                // inputs and of the sines: measured against 1 at least.
                let scale = want.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
                let e = scaled_error(got, &want) * want_scale(&want) / scale;
                assert!(
                    e <= tolerance,
                    "{cc}: {} part {k} at sample {s}: off by {e:e}",
                    f.name
                );
                assert_eq!(*status, 0, "{cc}: {} at sample {s}", f.name);
                let batch = printed(out, &format!("{}_batch", f.name), k, s);
                assert!(
                    batch.0 == *status && same_bits(&batch.1, got),
                    "{cc}: {}_batch part {k} at sample {s} is not the single state's",
                    f.name
                );
            }
        }
    }
}

/// Whether two printed arrays are the same numbers (NaN where NaN).
fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
}

/// How far a `float` result may be from the `f64` one, scaled: the solves with M's factors
/// lose what M's condition number takes.
pub fn f32_tolerance(method: Method) -> f64 {
    if solves(method) {
        1e-2
    } else {
        1e-4
    }
}

/// Whether `method` solves with M's factors.
fn solves(method: Method) -> bool {
    matches!(
        method,
        Method::MassMatrixInverse
            | Method::ForwardDynamics
            | Method::FloatingMassMatrixInverse
            | Method::FloatingForwardDynamics
            | Method::FloatingForwardDynamicsDerivatives
    )
}
