//! Which C compilers build the drivers, and how: each compiler's language flags, and the
//! builds of one header (its sines and cosines from `<math.h>`, the header's default or its own
//! kernels, the multiply-adds fused, the derivatives' tangents in lanes); and the compiling and
//! running of them.

use super::{driver, parse, Robot, Run, State};
use std::path::Path;
use std::process::Command;

/// Whether this machine runs code compiled with `-mfma` (x86-64 with FMA).
fn fused_here() -> bool {
    #[cfg(target_arch = "x86_64")]
    return std::arch::is_x86_feature_detected!("fma");
    #[cfg(not(target_arch = "x86_64"))]
    return false;
}

/// The compilers found, each with its language flags and whether to build it also with the
/// header's default and own sines and cosines (beside `<math.h>`'s).
pub fn compilers() -> Vec<(&'static str, &'static [&'static str], bool)> {
    let candidates: [(&str, &[&str], bool); 3] = [
        ("gcc", &["-std=c99", "-x", "c", "-Wdouble-promotion"], true),
        (
            "clang",
            &["-std=c99", "-x", "c", "-Wdouble-promotion"],
            true,
        ),
        ("g++", &["-std=c++17", "-x", "c++"], false),
    ];
    candidates
        .into_iter()
        .filter(|(cc, _, _)| Command::new(cc).arg("--version").output().is_ok())
        .collect()
}

/// The builds of `header` by one compiler, each a name and its extra flags: `<math.h>`'s sines
/// and cosines; with `kernels`, the default (the runtime's kernels, `<math.h>`'s beyond their
/// range), the kernels alone and the multiply-adds fused (as the Rust's are on a CPU with FMA);
/// and the derivatives' tangents in lanes (by default only where gcc targets AVX-512), as
/// portable loops on any CPU.
pub fn builds(header: &str, kernels: bool) -> Vec<(&'static str, &'static [&'static str])> {
    let mut builds: Vec<(&str, &[&str])> = vec![("libm", &["-DDYNAMICS_LIBM_SINCOS", "-lm"])];
    if kernels {
        builds.push(("default", &["-lm"]));
        // Smoothed friction's tanh is the one function the header's own trigonometry leaves
        // to the math library.
        if header.contains("tanh") {
            builds.push(("own", &["-DDYNAMICS_OWN_SINCOS", "-lm"]));
        } else {
            builds.push(("own", &["-DDYNAMICS_OWN_SINCOS"]));
        }
        if fused_here() {
            builds.push(("fused", &["-mfma", "-lm"]));
        }
    }
    if header.contains("#if DYNAMICS_TANGENT_LANES") {
        let lanes: &[&str] = &[
            "-DDYNAMICS_TANGENT_LANES=1",
            "-DDYNAMICS_LIBM_SINCOS",
            "-lm",
        ];
        builds.push(("lanes", lanes));
    }
    builds
}

/// Compiles `source` with `cc`, its `flags` and `extra`, to `program`, optimized (`-O1`, where
/// the compilers' flow analyses warn) or not; panics with the compiler's messages if it fails.
fn compile(cc: &str, flags: &[&str], extra: &[&str], optimize: bool, files: (&Path, &Path)) {
    let (source, program) = files;
    let out = Command::new(cc)
        .args(flags)
        .args(["-Wall", "-Wextra", "-Wpedantic", "-Werror"])
        .arg(if optimize { "-O1" } else { "-O0" })
        // No multiply-adds fused by the compiler (clang fuses within an expression by default,
        // where the target has them): the `double` results with `<math.h>` are then the
        // graph's evaluation bit for bit.
        .arg("-ffp-contract=off")
        .arg("-o")
        .arg(program)
        .arg(source)
        .args(extra)
        .output()
        .expect("run the compiler");
    let errors = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "{cc} {extra:?} on {source:?}:\n{errors}"
    );
}

/// How many ways a header is built.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Reach {
    /// One compiler, the cheapest found (clang builds a large header unoptimized in a third of
    /// gcc's time), with `<math.h>`'s sines and cosines (and the tangents in lanes, where the
    /// header has them), unoptimized: for a large header, or one whose code is of a kind
    /// another test builds every way.
    First,
    /// Every compiler, each with `<math.h>`'s (and the lanes), gcc's and g++'s first build of a
    /// small header optimized (see [`optimized`]): the header's own and default sines and
    /// cosines are the same text in every header, built every way on smaller ones.
    Compilers,
    /// Every compiler, every build, gcc's and g++'s first of a small header optimized.
    EveryWay,
}

/// Headers up to this size get an optimized build: gcc's flow analyses at `-O1` took 7 to 19 s
/// of CPU on PUMA 560's and the Panda's and warn on the emitters' code, which the small
/// headers of the same families show them.
const OPTIMIZED_UP_TO_BYTES: usize = 400_000;

/// Whether `cc`'s build `b` (0 the first) of `header` at `reach` is optimized (`-O1`): gcc's
/// and g++'s first, where their flow analyses warn (clang's warnings do not depend on the
/// optimization level), on a header small enough.
fn optimized(cc: &str, b: usize, header: &str, reach: Reach) -> bool {
    reach != Reach::First && b == 0 && cc != "clang" && header.len() <= OPTIMIZED_UP_TO_BYTES
}

/// The compilers of a build at `reach`: all, or the cheapest found.
fn compilers_for(reach: Reach) -> Vec<(&'static str, &'static [&'static str], bool)> {
    let mut all = compilers();
    if reach == Reach::First {
        if let Some(k) = all.iter().position(|(cc, _, _)| *cc == "clang") {
            all.swap(0, k);
        }
        all.truncate(1);
    }
    all
}

/// Compiles the header and driver of `robot` with every compiler (with `<math.h>`'s sines and
/// cosines, the default, and the header's own, linked without the math library where nothing
/// else needs it) and runs each program.
pub fn compile_and_run(robot: &Robot, states: &[State]) -> Vec<Run> {
    compile_and_run_builds(robot, states, Reach::EveryWay)
}

/// [`compile_and_run`], built as far as `reach` says. Optimizing a large header took most of
/// the command line's test time and finds nothing the small headers of the same code do not.
pub fn compile_and_run_builds(robot: &Robot, states: &[State], reach: Reach) -> Vec<Run> {
    // Two robots may share a name (the Panda's description file and its URDF), and tests run
    // side by side: a directory of their own per header.
    let mut hasher = std::collections::hash_map::DefaultHasher::new();
    std::hash::Hash::hash(&robot.header, &mut hasher);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "c_header_{}_{:016x}",
        robot.name,
        std::hash::Hasher::finish(&hasher)
    ));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    std::fs::write(dir.join(format!("{}.h", robot.name)), &robot.header).expect("write");
    let source = dir.join("driver.c");
    std::fs::write(&source, driver(robot, states)).expect("write");
    let mut runs = Vec::new();
    for (cc, flags, kernels_too) in compilers_for(reach) {
        // The builds differ only in what the header's macros select: the same IEEE results
        // (no contraction), most of them unoptimized.
        for (b, (name, extra)) in builds(&robot.header, kernels_too && reach == Reach::EveryWay)
            .into_iter()
            .enumerate()
        {
            let label = format!("{cc} {}", extra.join(" "));
            let program = dir.join(format!("driver_{cc}_{name}"));
            let optimize = optimized(cc, b, &robot.header, reach);
            compile(cc, flags, extra, optimize, (&source, &program));
            let run = Command::new(&program).output().expect("run the driver");
            assert!(run.status.success(), "{label} driver of {}", robot.name);
            let printed = parse(&String::from_utf8(run.stdout).expect("UTF-8"));
            runs.push(Run { label, printed });
        }
    }
    runs
}
